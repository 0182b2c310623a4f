#!/usr/bin/env python3
"""A pseudo-terminal for the emulated Pico's USB CDC port: prints the slave's name on stderr, then
copies its stdin to the master (bytes to the host program) and the master's output to its stdout (bytes
from the host program). The slave stays open here, so that a host closing and reopening it does not end
the bridge. Ends when stdin closes."""
import os
import pty
import select
import sys
import tty

master, slave = pty.openpty()
tty.setraw(slave)
sys.stderr.write(os.ttyname(slave) + "\n")
sys.stderr.flush()
stdin, stdout = sys.stdin.fileno(), sys.stdout.fileno()
while True:
    ready, _, _ = select.select([stdin, master], [], [])
    if stdin in ready:
        data = os.read(stdin, 4096)
        if not data:
            break
        os.write(master, data)
    if master in ready:
        try:
            data = os.read(master, 4096)
        except OSError:
            continue
        if data:
            os.write(stdout, data)
