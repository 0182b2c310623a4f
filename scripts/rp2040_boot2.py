#!/usr/bin/env python3
"""Pads the RP2040 boot stage 2 (firmware/rp2040/boot2.S, as a raw binary) to 252 bytes and appends the
CRC32 the boot ROM checks (RP2040 datasheet 2.8.1.3.1: polynomial 0x04C11DB7, initial value 0xFFFFFFFF,
no reflection, no final XOR, stored little-endian), then writes it as an assembler file placing the 256
bytes in the .boot2 section.

Usage: rp2040_boot2.py BOOT2.bin OUT.S"""
import sys


def crc32_boot_rom(data: bytes) -> int:
    crc = 0xFFFFFFFF
    for byte in data:
        crc ^= byte << 24
        for _ in range(8):
            crc = ((crc << 1) ^ 0x04C11DB7) if crc & 0x80000000 else crc << 1
            crc &= 0xFFFFFFFF
    return crc


def padded(code: bytes) -> bytes:
    if len(code) > 252:
        raise SystemExit(f"rp2040_boot2: boot stage 2 is {len(code)} bytes; at most 252 fit")
    body = code + bytes(252 - len(code))
    return body + crc32_boot_rom(body).to_bytes(4, "little")


def main() -> int:
    if len(sys.argv) != 3:
        print(__doc__.splitlines()[-1], file=sys.stderr)
        return 2
    with open(sys.argv[1], "rb") as f:
        image = padded(f.read())
    lines = ["// Written by scripts/rp2040_boot2.py: boot stage 2 with its CRC32.", '.section .boot2, "ax"']
    for i in range(0, 256, 16):
        lines.append(".byte " + ", ".join(f"0x{b:02x}" for b in image[i:i + 16]))
    with open(sys.argv[2], "w") as f:
        f.write("\n".join(lines) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
