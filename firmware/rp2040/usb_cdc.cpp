#include "rp2040/usb_cdc.hpp"

#include "rp2040/regs.hpp"
#include "rp2040/usb_descriptors.hpp"

namespace rp2040 {
namespace {

using namespace rp;

constexpr unsigned ep_in = usbdesc::ep_data_in & 0x0F, ep_out = usbdesc::ep_data_out,
                   ep_notify = usbdesc::ep_notify & 0x0F;
constexpr std::uint32_t in_buffers = 0x180, out_buffers = 0x200, notify_buffer = 0x280;  // DPRAM offsets
constexpr std::uint32_t packet = usbdesc::max_packet;

// USB 2.0 9.4 and CDC PSTN 6.3: the requests answered.
enum : std::uint8_t {
    get_status = 0,
    clear_feature = 1,
    set_address = 5,
    req_get_descriptor = 6,
    get_configuration = 8,
    set_configuration = 9,
    get_interface = 10,
    set_interface = 11
};
enum : std::uint8_t {
    set_line_coding = 0x20,
    get_line_coding = 0x21,
    set_control_line_state = 0x22,
    send_break = 0x23
};

// The controller's RAM is written a word at a time (its buffers are 64-byte aligned).
void to_dpram(std::uint32_t offset, const std::uint8_t* bytes, std::size_t n) {
    for (std::size_t i = 0; i < n; i += 4) {
        std::uint32_t w = 0;
        for (std::size_t k = 0; k < 4 && i + k < n; ++k) w |= static_cast<std::uint32_t>(bytes[i + k]) << (8 * k);
        reg(usb::dpram + offset + static_cast<std::uint32_t>(i)) = w;
    }
}
void from_dpram(std::uint32_t offset, std::uint8_t* bytes, std::size_t n) {
    for (std::size_t i = 0; i < n; i += 4) {
        std::uint32_t w = reg(usb::dpram + offset + static_cast<std::uint32_t>(i));
        for (std::size_t k = 0; k < 4 && i + k < n; ++k) bytes[i + k] = static_cast<std::uint8_t>(w >> (8 * k));
    }
}

// 4.1.2.5.1: the buffer control word first without AVAILABLE, then with it a few cycles later, as
// clk_sys runs faster than clk_usb.
void arm(std::uint32_t buf_ctrl, std::uint32_t word) {
    reg(buf_ctrl) = word;
    __asm volatile("nop\n nop\n nop\n nop\n nop\n nop");
    reg(buf_ctrl) = word | usb::buf_available;
}

}  // namespace

void UsbCdc::start(const char* serial) {
    serial_ = serial;
    for (std::uint32_t off = 0; off < 0x1000; off += 4) reg(usb::dpram + off) = 0;
    reg(usb::muxing) = usb::muxing_to_phy | usb::muxing_softcon;
    // No VBUS pin on the Pico's RP2040: VBUS is taken as present (the board is powered from it).
    reg(usb::pwr) = usb::pwr_vbus_detect | usb::pwr_vbus_detect_override;
    reg(usb::main_ctrl) = usb::main_controller_en;
    reg(usb::sie_ctrl) = usb::sie_ep0_int_1buf;
    reg(usb::inte) = usb::int_buff_status | usb::int_bus_reset | usb::int_setup_req;
    set_bits(usb::sie_ctrl, usb::sie_pullup_en);
}

void UsbCdc::on_irq() {
    std::uint32_t status = reg(usb::ints);
    if (status & usb::int_setup_req) {
        reg(usb::sie_status) = usb::status_setup_rec;
        on_setup();
    }
    if (status & usb::int_buff_status) {
        std::uint32_t done = reg(usb::buff_status);
        reg(usb::buff_status) = done;
        if (done & (1u << 0)) ep0_in_done();
        if (done & (1u << 1)) ep0_out_done();
        if (done & (1u << (2 * ep_in))) {
            in_.busy = false;
            bulk_in_kick();
        }
        if (done & (1u << (2 * ep_out + 1))) bulk_out_done();
    }
    if (status & usb::int_bus_reset) {
        reg(usb::sie_status) = usb::status_bus_reset;
        bus_reset();
    }
}

void UsbCdc::bus_reset() {
    reg(usb::addr_endp) = 0;
    configuration_ = 0;
    pending_address_ = 0;
    in_ = {};
    out_ = {};
    out_paused_ = false;
}

void UsbCdc::on_setup() {
    std::uint32_t w0 = reg(usb::dpram), w1 = reg(usb::dpram + 4);
    Setup s{static_cast<std::uint8_t>(w0), static_cast<std::uint8_t>(w0 >> 8), static_cast<std::uint16_t>(w0 >> 16),
            static_cast<std::uint16_t>(w1), static_cast<std::uint16_t>(w1 >> 16)};
    ep0_data1_ = true;  // every data or status stage starts with DATA1
    ep0_in_left_ = 0;
    switch (s.type & 0x60) {
        case 0x00:
            return standard_request(s);
        case 0x20:
            return class_request(s);
        default:
            return ep0_stall();
    }
}

void UsbCdc::standard_request(const Setup& s) {
    switch (s.request) {
        case req_get_descriptor:
            return get_descriptor(s);
        case set_address:
            pending_address_ = static_cast<std::uint8_t>(s.value & 0x7F);  // after the status stage
            return ep0_status_in();
        case set_configuration:
            if (s.value > 1) return ep0_stall();
            configuration_ = static_cast<std::uint8_t>(s.value);
            if (configuration_) configure_endpoints();
            return ep0_status_in();
        case get_configuration:
            ep0_reply_[0] = configuration_;
            return reply(ep0_reply_, 1, s.length);
        case get_status:
            ep0_reply_[0] = ep0_reply_[1] = 0;
            return reply(ep0_reply_, 2, s.length);
        case get_interface:
            ep0_reply_[0] = 0;
            return reply(ep0_reply_, 1, s.length);
        case set_interface:
            return s.value == 0 ? ep0_status_in() : ep0_stall();
        case clear_feature:
            // ENDPOINT_HALT: the endpoint's next packet is DATA0 again.
            if ((s.type & 0x1F) == 2) {
                if ((s.index & 0x7F) == ep_in) in_.data1 = false;
                if ((s.index & 0x7F) == ep_out) out_.data1 = false;
            }
            return ep0_status_in();
        default:
            return ep0_stall();
    }
}

void UsbCdc::class_request(const Setup& s) {
    switch (s.request) {
        case set_line_coding:
            return ep0_arm_out(true);
        case get_line_coding: {
            std::uint8_t* r = ep0_reply_;
            for (int i = 0; i < 4; ++i) r[i] = static_cast<std::uint8_t>(coding_.baud >> (8 * i));
            r[4] = coding_.stop_bits;
            r[5] = coding_.parity;
            r[6] = coding_.data_bits;
            return reply(r, 7, s.length);
        }
        case set_control_line_state:
            control_lines_ = s.value & 3;
            return ep0_status_in();
        case send_break:
            return ep0_status_in();
        default:
            return ep0_stall();
    }
}

void UsbCdc::get_descriptor(const Setup& s) {
    usbdesc::Bytes d{nullptr, 0};
    switch (s.value >> 8) {
        case 1:
            d = usbdesc::device();
            break;
        case 2:
            d = usbdesc::configuration();
            break;
        case 3:
            d = usbdesc::string(static_cast<std::uint8_t>(s.value), serial_, string_buffer_);
            break;
        default:
            break;  // no device qualifier: a full-speed-only device stalls it (USB 2.0 9.6.2)
    }
    if (!d.data) return ep0_stall();
    reply(d.data, d.size, s.length);
}

void UsbCdc::reply(const std::uint8_t* data, std::size_t size, std::uint16_t asked) {
    if (size > asked) size = asked;
    ep0_in_ = data;
    ep0_in_left_ = size;
    // A reply shorter than asked whose last packet is full ends with a zero-length packet.
    ep0_in_zlp_ = size < asked && size % packet == 0;
    ep0_in_next();
}

void UsbCdc::ep0_in_next() {
    std::size_t n = ep0_in_left_ < packet ? ep0_in_left_ : packet;
    to_dpram(usb::ep0_buffer, ep0_in_, n);
    ep0_in_ += n;
    ep0_in_left_ -= n;
    if (n < packet) ep0_in_zlp_ = false;  // this one is the short packet
    arm(usb::buf_ctrl(0, true),
        static_cast<std::uint32_t>(n) | usb::buf_full | (ep0_data1_ ? usb::buf_data1 : 0) | usb::buf_last);
    ep0_data1_ = !ep0_data1_;
}

void UsbCdc::ep0_status_in() {
    ep0_in_ = nullptr;
    ep0_in_left_ = 0;
    ep0_in_zlp_ = false;
    arm(usb::buf_ctrl(0, true), usb::buf_full | usb::buf_data1 | usb::buf_last);
    ep0_data1_ = false;
}

void UsbCdc::ep0_arm_out(bool data_stage) {
    ep0_out_data_ = data_stage;
    arm(usb::buf_ctrl(0, false), packet | usb::buf_data1 | usb::buf_last);
}

void UsbCdc::ep0_stall() {
    reg(usb::ep_stall_arm) = 3;
    reg(usb::buf_ctrl(0, true)) = usb::buf_stall;
    reg(usb::buf_ctrl(0, false)) = usb::buf_stall;
}

void UsbCdc::ep0_in_done() {
    if (pending_address_) {
        reg(usb::addr_endp) = pending_address_;  // the status stage went at the old address
        pending_address_ = 0;
        return;
    }
    if (ep0_in_left_ || ep0_in_zlp_) return ep0_in_next();
    if (ep0_in_) {
        ep0_in_ = nullptr;
        ep0_arm_out(false);  // the host's zero-length status packet
    }
}

void UsbCdc::ep0_out_done() {
    if (!ep0_out_data_) return;  // a status stage: the transfer is over
    ep0_out_data_ = false;
    std::uint8_t d[8] = {};
    from_dpram(usb::ep0_buffer, d, 7);
    coding_.baud = static_cast<std::uint32_t>(d[0] | d[1] << 8 | d[2] << 16 | d[3] << 24);
    coding_.stop_bits = d[4];
    coding_.parity = d[5];
    coding_.data_bits = d[6];
    ep0_status_in();
}

void UsbCdc::configure_endpoints() {
    reg(usb::ep_ctrl(ep_notify, true)) =
        usb::ep_enable | usb::ep_int_per_buffer | usb::ep_type_interrupt | notify_buffer;
    reg(usb::ep_ctrl(ep_in, true)) = usb::ep_enable | usb::ep_int_per_buffer | usb::ep_type_bulk | in_buffers;
    reg(usb::ep_ctrl(ep_out, false)) = usb::ep_enable | usb::ep_int_per_buffer | usb::ep_type_bulk | out_buffers;
    in_ = {};
    out_ = {};
    bulk_out_arm();
    bulk_in_kick();
}

// Sends the next packet from the transmit ring, in the buffer not used last.
void UsbCdc::bulk_in_kick() {
    if (!configured() || in_.busy || !tx_.held()) return;
    std::uint8_t chunk[packet];
    std::size_t n = tx_.held() < packet ? tx_.held() : packet;
    for (std::size_t i = 0; i < n; ++i) chunk[i] = tx_.bytes[tx_.tail++ % sizeof tx_.bytes];
    std::uint32_t at = in_buffers + packet * in_.buffer;
    to_dpram(at, chunk, n);
    reg(usb::ep_ctrl(ep_in, true)) = usb::ep_enable | usb::ep_int_per_buffer | usb::ep_type_bulk | at;
    arm(usb::buf_ctrl(ep_in, true), static_cast<std::uint32_t>(n) | usb::buf_full | (in_.data1 ? usb::buf_data1 : 0));
    in_.data1 = !in_.data1;
    in_.buffer ^= 1;
    in_.busy = true;
}

// Offers the next OUT buffer to the host, when the receive ring can take a whole packet.
void UsbCdc::bulk_out_arm() {
    if (rx_.room() < packet) {
        out_paused_ = true;  // the host is NAKed until read() makes room
        return;
    }
    out_paused_ = false;
    std::uint32_t at = out_buffers + packet * out_.buffer;
    reg(usb::ep_ctrl(ep_out, false)) = usb::ep_enable | usb::ep_int_per_buffer | usb::ep_type_bulk | at;
    arm(usb::buf_ctrl(ep_out, false), packet | (out_.data1 ? usb::buf_data1 : 0));
    out_.busy = true;
}

void UsbCdc::bulk_out_done() {
    std::uint32_t at = out_buffers + packet * out_.buffer;
    std::size_t n = reg(usb::buf_ctrl(ep_out, false)) & usb::buf_len;
    std::uint8_t chunk[packet];
    from_dpram(at, chunk, n);
    for (std::size_t i = 0; i < n; ++i) rx_.bytes[rx_.head++ % sizeof rx_.bytes] = chunk[i];
    out_.data1 = !out_.data1;
    out_.buffer ^= 1;
    out_.busy = false;
    bulk_out_arm();
}

std::size_t UsbCdc::read(std::uint8_t* out, std::size_t max) {
    irq_off();
    std::size_t n = 0;
    while (n < max && rx_.held()) out[n++] = rx_.bytes[rx_.tail++ % sizeof rx_.bytes];
    if (out_paused_ && configured()) bulk_out_arm();
    irq_on();
    return n;
}

bool UsbCdc::write(const std::uint8_t* bytes, std::size_t n) {
    irq_off();
    bool fits = configured() && tx_.room() >= n;
    if (fits) {
        for (std::size_t i = 0; i < n; ++i) tx_.bytes[tx_.head++ % sizeof tx_.bytes] = bytes[i];
        bulk_in_kick();
    }
    irq_on();
    return fits;
}

}  // namespace rp2040
