// What the emulated Pico's pins are wired to (firmware/rp2040/pins.hpp): a ФС-1501 reader, a punch, or
// a control reading through the emulate role. Each works on the emulator's own clock (virtual time),
// as the hardware would, and counts what a test checks.

const pin = (mcu, n) => mcu.gpio[n];
const outHigh = (mcu, n) => pin(mcu, n).outputValue;
// An input is changed only when its level changes: the emulated pin takes every write as an edge.
function setIn(mcu, n, level) {
  const p = pin(mcu, n);
  if (p.lastSet === level) return;
  p.lastSet = level;
  p.setInputValue(level);
}
const bus = (mcu, first) => {
  let v = 0;
  for (let t = 0; t < 8; t++) if (outHigh(mcu, first + t)) v |= 1 << t;
  return v;
};

// The reader: while its start line (GP19) is high it reads a frame every 1/rate s, the eight tracks on
// GP10..GP17 and a sprocket pulse on GP18; GP20 high reads backwards; past the tape's end GP21 (tape
// out) goes high. It stops at once when the start line falls (frames after that are counted).
export class Reader {
  constructor(mcu, tape, { rate = 1500, headAtEnd = false } = {}) {
    Object.assign(this, { mcu, tape, period: 1e9 / rate, pos: headAtEnd ? tape.length - 1 : 0 });
    this.running = false;
    this.sprockets = 0;
    this.afterStop = 0;
    this.frameAlarm = mcu.clock.createAlarm(() => this.frame());
    this.sprocketAlarm = mcu.clock.createAlarm(() => setIn(mcu, 18, false));
    pin(mcu, 19).addListener(() => this.startStop());
    setIn(mcu, 21, tape.length === 0);
  }
  startStop() {
    const on = outHigh(this.mcu, 19);
    if (process.env.PICO_DEBUG) process.stderr.write(`reader: start line ${on} at ${this.mcu.clock.nanos / 1e6} ms, frame ${this.pos}\n`);
    if (on === this.running) return;
    this.running = on;
    if (on) this.frameAlarm.schedule(1e6); // up to speed in 1 ms
    else this.frameAlarm.cancel();
  }
  frame() {
    if (!this.running) return;
    const backwards = outHigh(this.mcu, 20);
    if (this.pos < 0 || this.pos >= this.tape.length) {
      setIn(this.mcu, 21, true);
      return;
    }
    const row = this.tape[this.pos];
    this.pos += backwards ? -1 : 1;
    for (let t = 0; t < 8; t++) setIn(this.mcu, 10 + t, (row >> t) & 1 ? true : false);
    setIn(this.mcu, 18, true);
    this.sprockets++;
    this.sprocketAlarm.schedule(this.period / 3);
    this.frameAlarm.schedule(this.period);
  }
  stats() {
    return { sprockets: this.sprockets, position: this.pos };
  }
}

// The punch: a row is punched when the feed-hole magnet (GP8) is energised, its tracks from the code
// magnets (GP0..GP7); its ready line (GP22) is low for a punch cycle (1/rate s) after each row.
export class Punch {
  constructor(mcu, { rate = 150 } = {}) {
    Object.assign(this, { mcu, cycle: 1e9 / rate, rows: [] });
    this.readyAlarm = mcu.clock.createAlarm(() => setIn(mcu, 22, true));
    setIn(mcu, 22, true);
    pin(mcu, 8).addListener(() => {
      if (!outHigh(mcu, 8)) return;
      this.rows.push(bus(mcu, 0));
      this.onRow?.(this.rows.at(-1));
      setIn(mcu, 22, false);
      this.readyAlarm.schedule(this.cycle);
    });
  }
}

// The control, reading through the emulate role with the default wiring (data GP0..GP7, strobe GP8,
// start/stop GP9, all active high): it takes the data at each strobe, and stops at a DC3 frame (0x93,
// ISO with even parity) and every stopEvery frames (0: never), starting again pauseUs later. Frames
// strobed after its stop are counted, per stop.
export class Control {
  constructor(mcu, { stopEvery = 0, pauseUs = 3000, stopCode = 0x93 } = {}) {
    Object.assign(this, { mcu, stopEvery, pauseUs, stopCode, taken: [], afterStop: [], run: false });
    this.startAlarm = mcu.clock.createAlarm(() => this.setRun(true));
    this.startAlarm.schedule(5e6);
    pin(mcu, 8).addListener(() => {
      if (outHigh(mcu, 8)) this.strobe();
    });
  }
  setRun(on) {
    this.run = on;
    setIn(this.mcu, 9, on);
    if (!on) {
      this.afterStop.push(0);
      this.startAlarm.schedule(this.pauseUs * 1000);
    }
  }
  strobe() {
    const frame = bus(this.mcu, 0);
    this.taken.push(frame);
    this.onRow?.(frame);
    if (!this.run) {
      this.afterStop[this.afterStop.length - 1]++;
      return;
    }
    const every = this.stopEvery && this.taken.length % this.stopEvery === 0;
    if (frame === this.stopCode || every) this.setRun(false);
  }
}
