#!/usr/bin/env python3
"""Writes a UF2 file (Microsoft's USB flashing format, as the RP2040 boot ROM's mass-storage device takes
it) from an ELF image: the bytes of every loadable segment whose load address lies in the flash,
256 bytes a block, each block naming its flash address, with the RP2040 family id.

Usage: elf2uf2.py IMAGE.elf OUT.uf2"""
import os
import struct
import sys

UF2_MAGIC0, UF2_MAGIC1, UF2_MAGIC_END = 0x0A324655, 0x9E5D5157, 0x0AB16F30
FLAG_FAMILY_ID = 0x00002000
RP2040_FAMILY = 0xE48BFF56
FLASH_START, FLASH_END = 0x10000000, 0x11000000
PAYLOAD = 256


def flash_bytes(elf: bytes) -> dict:
    """{address: byte} of the loadable segments in flash (by physical, i.e. load, address)."""
    if elf[:4] != b"\x7fELF" or elf[4] != 1 or elf[5] != 1:
        raise ValueError("not a 32-bit little-endian ELF file")
    phoff, = struct.unpack_from("<I", elf, 28)
    phentsize, phnum = struct.unpack_from("<HH", elf, 42)
    image = {}
    for i in range(phnum):
        p_type, offset, _vaddr, paddr, filesz, _memsz, _flags, _align = struct.unpack_from(
            "<8I", elf, phoff + i * phentsize)
        if p_type != 1 or filesz == 0:
            continue
        if not (FLASH_START <= paddr and paddr + filesz <= FLASH_END):
            raise ValueError(f"segment at 0x{paddr:08x} ({filesz} bytes) is not in the flash")
        for k in range(filesz):
            image[paddr + k] = elf[offset + k]
    if not image:
        raise ValueError("no loadable bytes for the flash")
    return image


def uf2_blocks(image: dict) -> bytes:
    pages = sorted({a - a % PAYLOAD for a in image})
    out = bytearray()
    for n, page in enumerate(pages):
        data = bytes(image.get(page + k, 0) for k in range(PAYLOAD))
        header = struct.pack("<8I", UF2_MAGIC0, UF2_MAGIC1, FLAG_FAMILY_ID, page, PAYLOAD, n, len(pages),
                             RP2040_FAMILY)
        out += header + data + bytes(476 - PAYLOAD) + struct.pack("<I", UF2_MAGIC_END)
    return bytes(out)


def main() -> int:
    if len(sys.argv) != 3:
        print(__doc__.splitlines()[-1], file=sys.stderr)
        return 2
    try:
        with open(sys.argv[1], "rb") as f:
            blocks = uf2_blocks(flash_bytes(f.read()))
    except (OSError, ValueError, struct.error) as e:
        print(f"elf2uf2: {sys.argv[1]}: {e}", file=sys.stderr)
        return 1
    tmp = sys.argv[2] + ".tmp"
    with open(tmp, "wb") as f:
        f.write(blocks)
    os.replace(tmp, sys.argv[2])  # never a half-written UF2 under the name
    return 0


if __name__ == "__main__":
    sys.exit(main())
