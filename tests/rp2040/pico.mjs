#!/usr/bin/env node
// Runs the tape adapter's RP2040 firmware (the real .elf) on an emulated RP2040 (rp2040js), its USB
// CDC port bridged to a pseudo-terminal, its pins wired to an emulated reader, punch or control
// (units.mjs). Prints "adapter:/dev/pts/N" on stdout once the host has enumerated the device; on
// SIGTERM or SIGINT writes what the units saw and exits 0.
//
// rp2040js ships no boot ROM image, so this does the ROM's part of booting from flash (datasheet
// 2.8.1): it checks boot stage 2's CRC32, copies it to SRAM at 0x20041F00 and runs it, with lr 0, so
// that it enters the firmware through the vector table at 0x10000100. The firmware calls no ROM routine.
// The flash chip is not emulated either; its answer to the unique-id command (0x4B) is --flash-id.
//
// Usage: pico.mjs IMAGE.elf [--tape FILE [--head-at-end]] [--punch] [--control] [--stop-every N]
//        [--flash-id HEX16] [--usb-dump FILE] [--out DIR] [--speed X]
import { spawn } from 'node:child_process';
import { appendFileSync, readFileSync, writeFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { boot2CrcOk, loadFlash } from './elf.mjs';
import { Control, Punch, Reader } from './units.mjs';
import { UsbHost } from './usb_host.mjs';

const here = dirname(fileURLToPath(import.meta.url));
const { RP2040, ConsoleLogger, LogLevel } = createRequire(import.meta.url)('rp2040js');

function options(argv) {
  const o = { elf: argv[0], speed: 1, flashId: '0000000000000000', out: null };
  for (let i = 1; i < argv.length; i++) {
    const a = argv[i];
    const value = () => argv[++i];
    if (a === '--tape') o.tape = value();
    else if (a === '--head-at-end') o.headAtEnd = true;
    else if (a === '--punch') o.punch = true;
    else if (a === '--control') o.control = true;
    else if (a === '--stop-every') o.stopEvery = Number(value());
    else if (a === '--flash-id') o.flashId = value();
    else if (a === '--usb-dump') o.usbDump = value();
    else if (a === '--out') o.out = value();
    else if (a === '--speed') o.speed = Number(value());
    else throw new Error(`unknown option ${a}`);
  }
  if (!o.elf) throw new Error('no image: pico.mjs IMAGE.elf [options]');
  return o;
}

// The W25Q's answer to 0x4B: four dummy bytes, then the 64-bit id, one byte per frame read.
function emulateFlashId(mcu, idHex) {
  const ssi = mcu.peripherals[0x18000]; // XIP_SSI at 0x18000000
  const id = Buffer.from(idHex, 'hex');
  const fifo = [];
  let sent = 0;
  const write = ssi.writeUint32.bind(ssi), read = ssi.readUint32.bind(ssi);
  ssi.writeUint32 = (offset, value) => {
    if (offset === 0x60 && (ssi.crtlr0 >> 8 & 3) === 0) {
      sent = value === 0x4b && fifo.length === 0 ? 1 : sent + 1;
      fifo.push(sent >= 6 && sent <= 13 ? id[sent - 6] : 0);
      return;
    }
    write(offset, value);
  };
  ssi.readUint32 = (offset) => (offset === 0x60 && fifo.length ? fifo.shift() : read(offset));
}

function boot(mcu, elf, flashId) {
  loadFlash(elf, mcu.flash);
  if (!boot2CrcOk(mcu.flash)) throw new Error(`${elf}: boot stage 2 fails its CRC32: the boot ROM would not run it`);
  emulateFlashId(mcu, flashId);
  mcu.sram.set(mcu.flash.subarray(0, 256), 0x41f00);
  mcu.core.SP = 0x20042000;
  mcu.core.LR = 0;
  mcu.core.PC = 0x20041f00;
}

function bridge(host) {
  const pty = spawn('python3', [join(here, 'pty_bridge.py')], { stdio: ['pipe', 'pipe', 'pipe'] });
  pty.stdout.on('data', (bytes) => host.send(bytes));
  host.onData = (bytes) => pty.stdin.write(bytes);
  return new Promise((resolve, reject) => {
    let err = '';
    pty.stderr.on('data', (d) => {
      err += d;
      if (err.includes('\n')) resolve({ pty, name: err.split('\n')[0] });
    });
    pty.on('exit', () => reject(new Error(`pty bridge ended: ${err}`)));
  });
}

// Runs the emulated chip no faster than real time (times speed), in slices that let I/O in between.
// A slice runs at most 2 ms of the chip's time: after the process was not scheduled for a while, the
// chip falls behind instead of catching up in a burst, which would compress, in the host's real time,
// the adapter's time-outs (its 500 ms watchdog among them).
function run(mcu, speed) {
  const t0 = performance.now(), n0 = mcu.clock.nanos;
  let last = t0;
  const slice = () => {
    const now = performance.now();
    const target = mcu.clock.nanos + Math.min((now - last) * 1e6 * speed, 2e6);
    last = now;
    for (let i = 0; i < 100000 && mcu.clock.nanos < target; i++) {
      if (mcu.core.waiting) {
        const next = mcu.clock.nanosToNextAlarm;
        mcu.clock.tick(next > 0 ? Math.min(next, target - mcu.clock.nanos) : target - mcu.clock.nanos);
      } else {
        mcu.clock.tick(mcu.core.executeInstruction() * 8); // 125 MHz
      }
    }
    setImmediate(slice);
  };
  slice();
  return () => (mcu.clock.nanos - n0) / ((performance.now() - t0) * 1e6);
}

async function main() {
  const o = options(process.argv.slice(2));
  const mcu = new RP2040();
  mcu.logger = new ConsoleLogger(LogLevel.Error);
  boot(mcu, o.elf, o.flashId);
  const units = {};
  if (o.tape) units.reader = new Reader(mcu, readFileSync(o.tape), { headAtEnd: o.headAtEnd });
  if (o.punch) units.punch = new Punch(mcu);
  if (o.control) units.control = new Control(mcu, { stopEvery: o.stopEvery || 0 });
  const host = new UsbHost(mcu.usbCtrl, (m) => process.stderr.write(`pico: ${m}\n`));
  const { pty, name } = await bridge(host);
  const ratio = run(mcu, o.speed);
  host.onReady = () => {
    if (o.usbDump) writeFileSync(o.usbDump, host.dump);
    process.stdout.write(`adapter:${name}\n`);
  };
  // What the punch punched and the control took, each row as it comes (a test waits on them).
  if (o.out) {
    for (const [unit, file] of [[units.punch, 'punched.bin'], [units.control, 'taken.bin']]) {
      if (!unit) continue;
      const path = join(o.out, file);
      writeFileSync(path, '');
      unit.onRow = (row) => appendFileSync(path, Uint8Array.of(row));
    }
  }
  const finish = () => {
    if (o.out) {
      const stats = { virtual_per_real: ratio(), virtual_ms: mcu.clock.nanos / 1e6 };
      if (units.reader) Object.assign(stats, units.reader.stats());
      if (units.control) stats.frames_after_stop = units.control.afterStop;
      writeFileSync(join(o.out, 'stats.json'), JSON.stringify(stats) + '\n');
    }
    pty.kill();
    process.exit(0);
  };
  process.on('SIGTERM', finish);
  process.on('SIGINT', finish);
}

main().catch((e) => {
  process.stderr.write(`pico: ${e.message}\n`);
  process.exit(1);
});
