// A USB full-speed CDC-ACM device on the RP2040's USB controller (datasheet 4.1), written for this
// adapter: enumeration on endpoint 0 (SET_ADDRESS, GET_DESCRIPTOR, SET_CONFIGURATION, the ACM class
// requests), and the data interface's bulk endpoints as a byte stream in both directions.
//
// Each bulk endpoint has two 64-byte buffers in the controller's RAM, used in turn: the next packet is
// filled (IN) or the last one emptied (OUT) while the other buffer is on the bus. The controller's own
// double-buffer mode (both buffers armed at once) is not used: the emulated controller CI runs on
// (rp2040js 1.4.1) sends an IN endpoint's two buffers in the wrong order and fills only buffer 0 on OUT.
// Everything runs in the USB interrupt except read() and write(), the main loop's side, which mask it.
#pragma once

#include <cstddef>
#include <cstdint>

namespace rp2040 {

struct LineCoding {
    std::uint32_t baud = 115200;
    std::uint8_t stop_bits = 0, parity = 0, data_bits = 8;
};

class UsbCdc {
public:
    /// Starts the controller and connects (pull-up on D+); serial is kept for the string descriptor.
    void start(const char* serial);
    /// The controller's interrupt.
    void on_irq();
    /// Bytes the host sent, up to max; 0 when none.
    std::size_t read(std::uint8_t* out, std::size_t max);
    /// Queues all n bytes for the host, or none (false) when they do not fit now.
    bool write(const std::uint8_t* bytes, std::size_t n);
    bool configured() const { return configuration_ != 0; }
    const LineCoding& line_coding() const { return coding_; }
    /// DTR and RTS as the host last set them (SET_CONTROL_LINE_STATE bits 0 and 1).
    std::uint16_t control_lines() const { return control_lines_; }

private:
    struct Setup {
        std::uint8_t type, request;
        std::uint16_t value, index, length;
    };
    template <std::size_t N>
    struct Ring {
        std::uint8_t bytes[N];
        std::uint32_t head = 0, tail = 0;  // free-running; head - tail bytes held
        std::size_t held() const { return head - tail; }
        std::size_t room() const { return N - held(); }
    };
    struct Bulk {
        std::uint8_t buffer = 0;  // the buffer (0, 1) to use next
        bool data1 = false;       // the next packet's PID
        bool busy = false;        // a buffer is armed
    };

    const char* serial_ = "";
    std::uint8_t configuration_ = 0;
    std::uint8_t pending_address_ = 0;
    bool ep0_data1_ = true;
    const std::uint8_t* ep0_in_ = nullptr;  // IN data stage still to send
    std::size_t ep0_in_left_ = 0;
    bool ep0_in_zlp_ = false;    // the data stage ends with a zero-length packet
    bool ep0_out_data_ = false;  // the armed EP0 OUT buffer is a data stage (SET_LINE_CODING)
    std::uint8_t ep0_reply_[8] = {};
    std::uint8_t string_buffer_[64] = {};
    LineCoding coding_{};
    std::uint16_t control_lines_ = 0;
    Bulk in_{}, out_{};
    bool out_paused_ = false;  // OUT not re-armed: the receive ring had no room for a packet
    Ring<512> rx_{};
    Ring<1024> tx_{};

    void bus_reset();
    void on_setup();
    void standard_request(const Setup& s);
    void class_request(const Setup& s);
    void get_descriptor(const Setup& s);
    void reply(const std::uint8_t* data, std::size_t size, std::uint16_t asked);
    void ep0_in_next();
    void ep0_status_in();
    void ep0_arm_out(bool data_stage);
    void ep0_stall();
    void ep0_in_done();
    void ep0_out_done();
    void configure_endpoints();
    void bulk_in_kick();
    void bulk_out_arm();
    void bulk_out_done();
};

}  // namespace rp2040
