#!/usr/bin/env python3
"""The RP2040 image's tools: scripts/elf2uf2.py (UF2 blocks from an ELF's flash segments) and
scripts/rp2040_boot2.py (boot stage 2 padded with the CRC32 the boot ROM checks)."""
import os
import struct
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import elf2uf2  # noqa: E402
import rp2040_boot2  # noqa: E402


def elf(segments):
    """A 32-bit little-endian ARM ELF with one PT_LOAD program header per (paddr, bytes, type)."""
    phoff, phentsize = 52, 32
    data_at = phoff + phentsize * len(segments)
    header = b"\x7fELF" + bytes([1, 1, 1]) + bytes(9)
    header += struct.pack("<HHIIIIIHHHHHH", 2, 40, 1, 0, phoff, 0, 0, 52, phentsize, len(segments), 40, 0, 0)
    phdrs, blob = b"", b""
    for paddr, data, ptype in segments:
        phdrs += struct.pack("<8I", ptype, data_at + len(blob), paddr, paddr, len(data), len(data), 5, 4)
        blob += data
    return header + phdrs + blob


def blocks(uf2):
    out = []
    for i in range(0, len(uf2), 512):
        b = uf2[i:i + 512]
        m0, m1, flags, addr, size, n, total, family = struct.unpack_from("<8I", b)
        end, = struct.unpack_from("<I", b, 508)
        out.append(dict(m0=m0, m1=m1, flags=flags, addr=addr, size=size, n=n, total=total, family=family,
                        data=b[32:32 + size], pad=b[32 + size:508], end=end))
    return out


class Elf2Uf2(unittest.TestCase):
    def test_every_flash_byte_in_a_256_byte_block_at_its_address(self):
        code = bytes((i * 7) & 0xFF for i in range(300))
        tail = b"0123456789"
        image = elf([(0x10000000, code, 1), (0x10000400, tail, 1), (0x20000000, b"ram", 6)])
        got = blocks(elf2uf2.uf2_blocks(elf2uf2.flash_bytes(image)))
        self.assertEqual([b["addr"] for b in got], [0x10000000, 0x10000100, 0x10000400])
        for n, b in enumerate(got):
            self.assertEqual((b["m0"], b["m1"], b["end"]), (0x0A324655, 0x9E5D5157, 0x0AB16F30))
            self.assertEqual((b["flags"], b["family"]), (0x2000, 0xE48BFF56))
            self.assertEqual((b["size"], b["n"], b["total"]), (256, n, 3))
            self.assertEqual(b["pad"], bytes(476 - 256))
        self.assertEqual(got[0]["data"], code[:256])
        self.assertEqual(got[1]["data"], code[256:] + bytes(256 - 44))
        self.assertEqual(got[2]["data"], tail + bytes(246))

    def test_a_segment_outside_the_flash_is_refused_and_nothing_is_written(self):
        with tempfile.TemporaryDirectory() as d:
            src, out = os.path.join(d, "x.elf"), os.path.join(d, "x.uf2")
            with open(src, "wb") as f:
                f.write(elf([(0x20000000, b"abcd", 1)]))
            r = subprocess.run([sys.executable, os.path.join(ROOT, "scripts/elf2uf2.py"), src, out],
                               capture_output=True, text=True)
            self.assertEqual(r.returncode, 1)
            self.assertIn("not in the flash", r.stderr)
            self.assertFalse(os.path.exists(out))


class Boot2(unittest.TestCase):
    def test_crc_is_the_boot_roms(self):
        # CRC-32/MPEG-2 (the boot ROM's: polynomial 0x04C11DB7, init 0xFFFFFFFF, no reflection): check value.
        self.assertEqual(rp2040_boot2.crc32_boot_rom(b"123456789"), 0x0376E6E7)

    def test_padded_to_252_bytes_then_its_crc_little_endian(self):
        image = rp2040_boot2.padded(b"\x01\x02\x03")
        self.assertEqual(len(image), 256)
        self.assertEqual(image[3:252], bytes(249))
        self.assertEqual(struct.unpack("<I", image[252:])[0], rp2040_boot2.crc32_boot_rom(image[:252]))

    def test_too_long_is_refused(self):
        with self.assertRaises(SystemExit):
            rp2040_boot2.padded(bytes(253))


if __name__ == "__main__":
    unittest.main()
