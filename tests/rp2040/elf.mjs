// The loadable bytes of an ELF image that go into the flash (by their load address).
import { readFileSync } from 'node:fs';

export const FLASH = 0x10000000;

export function loadFlash(path, flash) {
  const elf = readFileSync(path);
  if (elf.readUInt32BE(0) !== 0x7f454c46 || elf[4] !== 1 || elf[5] !== 1) {
    throw new Error(`${path}: not a 32-bit little-endian ELF file`);
  }
  const phoff = elf.readUInt32LE(28), phentsize = elf.readUInt16LE(42), phnum = elf.readUInt16LE(44);
  let end = 0;
  for (let i = 0; i < phnum; i++) {
    const at = phoff + i * phentsize;
    const [type, offset, , paddr, filesz] = [0, 4, 8, 12, 16].map((k) => elf.readUInt32LE(at + k));
    if (type !== 1 || filesz === 0) continue;
    if (paddr < FLASH || paddr + filesz > FLASH + flash.length) throw new Error(`${path}: segment at ${paddr.toString(16)} outside the flash`);
    flash.set(elf.subarray(offset, offset + filesz), paddr - FLASH);
    end = Math.max(end, paddr + filesz - FLASH);
  }
  return end;
}

// The boot ROM's check of boot stage 2: CRC32 (polynomial 0x04C11DB7, initial 0xFFFFFFFF, no reflection)
// of the first 252 bytes equals the next four, little-endian.
export function boot2CrcOk(flash) {
  let crc = 0xffffffff;
  for (let i = 0; i < 252; i++) {
    crc ^= flash[i] << 24;
    for (let b = 0; b < 8; b++) crc = crc & 0x80000000 ? ((crc << 1) ^ 0x04c11db7) >>> 0 : (crc << 1) >>> 0;
  }
  const stored = (flash[252] | (flash[253] << 8) | (flash[254] << 16) | (flash[255] << 24)) >>> 0;
  return crc >>> 0 === stored;
}
