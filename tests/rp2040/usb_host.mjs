// The USB host side of the emulated Pico: enumerates the device as a host would (its descriptors, an
// address, the configuration, the CDC ACM line coding and control lines), writes an `lsusb -v`-like
// dump, then carries the bulk data endpoints' bytes both ways. Built on the emulated controller's
// hooks (rp2040js RPUSBController: sendSetupPacket, onEndpointWrite, onEndpointRead, endpointReadDone).

const setup = (type, request, value, index, length) =>
  new Uint8Array([type, request, value & 0xff, value >> 8, index & 0xff, index >> 8, length & 0xff, length >> 8]);

export class UsbHost {
  constructor(usb, log) {
    this.usb = usb;
    this.log = log;
    this.transfer = null; // the control transfer under way
    this.queue = [];
    this.dataIn = -1;
    this.dataOut = -1;
    this.outPending = 0; // the device's OUT buffer is armed and waiting for bytes (its size)
    this.toDevice = [];
    this.onData = () => {};
    this.onReady = () => {};
    this.dump = '';
    usb.onUSBEnabled = () => usb.resetDevice();
    usb.onResetReceived = () => this.enumerate().catch((e) => this.log(`enumeration failed: ${e.message}`));
    usb.onEndpointWrite = (ep, buf) => this.endpointWrite(ep, buf);
    usb.onEndpointRead = (ep, size) => this.endpointRead(ep, size);
  }

  control(bytes, outData = null) {
    return new Promise((resolve) => {
      this.queue.push({ bytes, outData, resolve });
      if (!this.transfer) this.next();
    });
  }

  next() {
    this.transfer = this.queue.shift() || null;
    if (!this.transfer) return;
    const t = this.transfer;
    t.in = (t.bytes[0] & 0x80) !== 0;
    t.length = t.bytes[6] | (t.bytes[7] << 8);
    t.data = [];
    t.dataDone = !t.in;
    this.usb.sendSetupPacket(t.bytes);
  }

  finish(result) {
    const t = this.transfer;
    this.transfer = null;
    t.resolve(result);
    this.next();
  }

  endpointWrite(ep, buf) {
    if (ep === 0) {
      const t = this.transfer;
      if (!t) return;
      if (t.in && !t.dataDone) {
        t.data.push(...buf);
        if (buf.length < 64 || t.data.length >= t.length) {
          t.dataDone = true;
          if (t.statusAsked) this.statusOut();
        }
      } else if (!t.in && buf.length === 0) {
        this.finish(new Uint8Array(0)); // the device's status stage
      }
      return;
    }
    if (ep === this.dataIn) this.onData(buf);
  }

  endpointRead(ep, size) {
    if (ep === 0) {
      const t = this.transfer;
      if (!t) return;
      if (!t.in && t.outData && !t.outSent) {
        t.outSent = true;
        this.usb.endpointReadDone(0, t.outData);
      } else if (t.in) {
        // The emulated controller reports a packet sent before the host has it: the device may ask
        // for the status stage before the last data packet arrived.
        if (t.dataDone) this.statusOut();
        else t.statusAsked = true;
      }
      return;
    }
    if (ep === this.dataOut) {
      this.outPending = size;
      this.pump();
    }
  }

  statusOut() {
    this.usb.endpointReadDone(0, new Uint8Array(0)); // the host's zero-length status packet
    this.finish(Uint8Array.from(this.transfer.data));
  }

  send(bytes) {
    this.toDevice.push(...bytes);
    this.pump();
  }

  pump() {
    if (!this.outPending || !this.toDevice.length) return;
    const n = Math.min(this.outPending, 64, this.toDevice.length);
    const chunk = Uint8Array.from(this.toDevice.splice(0, n));
    this.outPending = 0;
    this.usb.endpointReadDone(this.dataOut, chunk);
  }

  async descriptor(type, index, length, lang = 0) {
    return this.control(setup(0x80, 6, (type << 8) | index, lang, length));
  }

  async enumerate() {
    const device0 = await this.descriptor(1, 0, 64);
    await this.control(setup(0x00, 5, 7, 0, 0)); // SET_ADDRESS 7
    const device = await this.descriptor(1, 0, 18);
    const head = await this.descriptor(2, 0, 9);
    const config = await this.descriptor(2, 0, head[2] | (head[3] << 8));
    const langs = await this.descriptor(3, 0, 255);
    const lang = langs[2] | (langs[3] << 8);
    const strings = {};
    for (const i of [device[14], device[15], device[16]]) {
      if (i) strings[i] = decodeString(await this.descriptor(3, i, 255, lang));
    }
    const eps = bulkEndpoints(config);
    this.dataIn = eps.in; // known before SET_CONFIGURATION, which arms the device's OUT endpoint
    this.dataOut = eps.out;
    await this.control(setup(0x00, 9, 1, 0, 0)); // SET_CONFIGURATION 1
    const coding = Uint8Array.from([0x00, 0xc2, 0x01, 0x00, 0, 0, 8]); // 115200 8N1
    await this.control(setup(0x21, 0x20, 0, 0, 7), coding);
    const back = await this.control(setup(0xa1, 0x21, 0, 0, 7));
    await this.control(setup(0x21, 0x22, 3, 0, 0)); // DTR and RTS
    this.dump = describe(device0, device, config, strings, langs, back);
    this.onReady();
  }
}

function decodeString(d) {
  let s = '';
  for (let i = 2; i + 1 < d[0] && i + 1 < d.length; i += 2) s += String.fromCharCode(d[i] | (d[i + 1] << 8));
  return s;
}

function* descriptors(config) {
  for (let i = 0; i + 1 < config.length && config[i] >= 2; i += config[i]) yield config.subarray(i, i + config[i]);
}

function bulkEndpoints(config) {
  const eps = { in: -1, out: -1 };
  let data = false;
  for (const d of descriptors(config)) {
    if (d[1] === 4) data = d[5] === 0x0a;
    if (d[1] === 5 && data && (d[3] & 3) === 2) eps[d[2] & 0x80 ? 'in' : 'out'] = d[2] & 0x0f;
  }
  return eps;
}

const hex = (v, w) => '0x' + v.toString(16).padStart(w, '0');
const u16 = (d, i) => d[i] | (d[i + 1] << 8);

// An `lsusb -v`-like dump: one field a line, indented by descriptor.
function describe(device0, d, config, strings, langs, coding) {
  const s = (i) => (i ? ` ${strings[i] ?? ''}` : '');
  const out = [
    `Device Descriptor (first read at address 0: ${device0.length} bytes, bMaxPacketSize0 ${device0[7]})`,
    `  bLength ${d[0]}`, `  bDescriptorType ${d[1]}`, `  bcdUSB ${(u16(d, 2) >> 8)}.${(u16(d, 2) & 0xff).toString(16).padStart(2, '0')}`,
    `  bDeviceClass ${d[4]}`, `  bDeviceSubClass ${d[5]}`, `  bDeviceProtocol ${d[6]}`, `  bMaxPacketSize0 ${d[7]}`,
    `  idVendor ${hex(u16(d, 8), 4)}`, `  idProduct ${hex(u16(d, 10), 4)}`, `  bcdDevice ${hex(u16(d, 12), 4)}`,
    `  iManufacturer ${d[14]}${s(d[14])}`, `  iProduct ${d[15]}${s(d[15])}`, `  iSerial ${d[16]}${s(d[16])}`,
    `  bNumConfigurations ${d[17]}`,
  ];
  for (const x of descriptors(config)) {
    if (x[1] === 2) {
      out.push('  Configuration Descriptor:', `    wTotalLength ${hex(u16(x, 2), 4)}`, `    bNumInterfaces ${x[4]}`,
        `    bConfigurationValue ${x[5]}`, `    bmAttributes ${hex(x[7], 2)}`, `    MaxPower ${x[8] * 2}mA`);
    } else if (x[1] === 4) {
      out.push('    Interface Descriptor:', `      bInterfaceNumber ${x[2]}`, `      bAlternateSetting ${x[3]}`,
        `      bNumEndpoints ${x[4]}`, `      bInterfaceClass ${x[5]}`, `      bInterfaceSubClass ${x[6]}`,
        `      bInterfaceProtocol ${x[7]}`);
    } else if (x[1] === 0x24) {
      out.push(`      CDC functional descriptor subtype ${hex(x[2], 2)}: ${Array.from(x.subarray(3), (b) => hex(b, 2)).join(' ')}`);
    } else if (x[1] === 5) {
      const kind = ['Control', 'Isochronous', 'Bulk', 'Interrupt'][x[3] & 3];
      out.push('      Endpoint Descriptor:', `        bEndpointAddress ${hex(x[2], 2)} EP ${x[2] & 15} ${x[2] & 0x80 ? 'IN' : 'OUT'}`,
        `        Transfer Type ${kind}`, `        wMaxPacketSize ${hex(u16(x, 4), 4)}`, `        bInterval ${x[6]}`);
    }
  }
  out.push(`String languages: ${hex(u16(langs, 2), 4)}`);
  out.push(`Line coding read back: ${u16(coding, 0) + (u16(coding, 2) << 16)} baud, ${coding[6]} data bits, parity ${coding[5]}, stop ${coding[4]}`);
  return out.join('\n') + '\n';
}
