#!/usr/bin/env python3
"""Writes the seed corpus of adapter_host_fuzz (corpus/adapter_host/): whole conversations of a good
adapter in the target's record format (flags, type, length, payload), one per thing the host does,
and a few with the faults the host must name. Run it again after a change to the protocol."""
import os
import struct

OK, INFO, ROWS, CREDIT, STATUS, ERROR, ECHO_REPLY = 0x82, 0x81, 0x83, 0x84, 0x85, 0x86, 0x8A
IN_STEP, BAD_CRC, QUIET = 1, 2, 4


def record(kind, payload=b"", flags=IN_STEP):
    return bytes([flags, kind, len(payload)]) + payload


def hello(caps=0x0F, read_buffer=1024, punch_buffer=256):
    info = struct.pack("<BBBBBBHHHH", 1, 1, 2, 3, caps, 0x0F, 1500, 150, read_buffer, punch_buffer) + b"FUZZ0001"
    return record(OK, b"\x09") + record(INFO, info)


def rows(first, data, flags=()):
    payload = struct.pack("<IB", first, len(data)) + bytes(data)
    for index, bits in flags:
        payload += bytes([index, bits])
    return record(ROWS, payload, flags=0)


def status(bits, frame):
    return record(STATUS, struct.pack("<HI", bits, frame), flags=0)


def credit(next_row, punched, free):
    return record(CREDIT, struct.pack("<IIH", next_row, punched, free), flags=0)


def error(code, about, frame):
    return record(ERROR, struct.pack("<BBI", code, about, frame), flags=0)


def seeds():
    tape = [0x25, 0x0A, 0x4E, 0x31, 0x47, 0x30, 0x31, 0x0A] * 12
    read = hello() + record(OK, b"\x03")
    yield "read-whole", bytes([0]) + read + rows(0, tape[:48]) + rows(48, tape[48:]) + status(1, len(tape))
    yield "read-reverse-flags", bytes([0x10]) + read + rows(0, tape[:40], [(3, 1), (4, 2)]) + status(1 << 9, 40)
    yield "read-gap-resent", bytes([0]) + read + rows(0, tape[:20]) + rows(40, tape[40:60]) + rows(
        20, tape[20:40]) + rows(40, tape[40:60]) + status(1, 60)
    yield "read-bad-crc", bytes([0]) + read + record(ROWS, b"\x00" * 10, BAD_CRC) + rows(0, tape[:10]) + status(1, 10)
    yield "read-torn", bytes([0]) + read + rows(0, tape[:30]) + status(2, 30)
    yield "read-tape-out-before-sent", bytes([0]) + read + rows(0, tape[:30]) + status(1, 10)
    yield "read-overrun", bytes([0]) + read + rows(0, tape[:30]) + error(8, 0, 30) + rows(30, tape[30:40])
    yield "read-quiet", bytes([0]) + read + record(0, b"", QUIET) * 4 + rows(0, tape[:8]) + status(1, 8)
    yield "read-every-packet-damaged", bytes([0]) + read + record(ROWS, b"\x01" * 20, BAD_CRC) * 8
    yield "read-no-reader", bytes([0]) + hello(caps=0x02)
    yield "punch-one", bytes([1]) + hello() + credit(1, 0, 255) + credit(1, 1, 256)
    yield "punch-many", bytes([1 + 4 * 20]) + hello() + credit(181, 0, 75) + credit(181, 100, 175) + credit(
        181, 181, 256)
    yield "punch-credit-beyond-ring", bytes([1]) + hello() + credit(1, 0, 9999)
    yield "punch-out-of-order", bytes([5]) + hello() + error(6, 5, 0) + credit(10, 10, 256)
    yield "punch-tape-out", bytes([5]) + hello() + credit(10, 3, 250) + status(1 << 10, 3)
    yield "configure-echo", bytes([2 + 4 * 8]) + hello() + record(OK, b"\x02") + record(ECHO_REPLY, bytes([0xA5] * 8))
    yield "feed", bytes([3 + 4]) + hello() + record(OK, b"\x06") + credit(0, 1, 256)
    yield "refused", bytes([2]) + hello() + record(ERROR, struct.pack("<BBI", 2, 2, 0))
    yield "other-protocol", bytes([0]) + record(OK, b"\x09") + record(INFO, b"\x07")


def main():
    folder = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus", "adapter_host")
    os.makedirs(folder, exist_ok=True)
    for name, data in seeds():
        with open(os.path.join(folder, name), "wb") as f:
            f.write(data)


if __name__ == "__main__":
    main()
