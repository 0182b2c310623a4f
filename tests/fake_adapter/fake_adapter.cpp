#include "fake_adapter.hpp"

#include <errno.h>
#include <fcntl.h>
#include <link.h>
#include <linux/hidraw.h>
#include <linux/usbdevice_fs.h>
#include <stdlib.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <umockdev.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <deque>
#include <mutex>
#include <thread>

#include "core/engine.hpp"
#include "core/protocol.hpp"

namespace fake {
namespace {

using clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

constexpr std::uint8_t bulk_in = 0x81, bulk_out = 0x01;
constexpr std::size_t endpoint_queue = 8;  ///< packets the adapter's IN endpoint buffers
constexpr auto hid_read_wait = 5ms;        ///< a read with nothing to give answers "nothing" after this
constexpr auto reap_wait = 2ms;            ///< so does a reap

// A vendor-defined page, 64-byte input and output reports, no report ids.
const std::uint8_t report_descriptor[] = {0x06, 0x00, 0xFF, 0x09, 0x01, 0xA1, 0x01, 0x15, 0x00,
                                          0x26, 0xFF, 0x00, 0x75, 0x08, 0x95, 0x40, 0x09, 0x01,
                                          0x81, 0x02, 0x95, 0x40, 0x09, 0x01, 0x91, 0x02, 0xC0};

std::string hex(const std::uint8_t* b, std::size_t n) {
    std::string s;
    char two[3];
    for (std::size_t i = 0; i < n; ++i) {
        std::snprintf(two, sizeof two, "%02x", b[i]);
        s += two;
    }
    return s;
}

// USB descriptors: device, then one configuration with a vendor interface (bulk) or a HID interface.
std::string descriptors(Link link) {
    std::vector<std::uint8_t> d = {18, 1, 0x00, 0x02, 0, 0, 0, 64, 0x09, 0x12, 0x01, 0x00, 0x00, 0x01, 1, 2, 3, 1};
    if (link == Link::usb) {
        std::vector<std::uint8_t> c = {9, 2, 32, 0, 1,       1, 0,  0x80, 50, 9, 4, 0,        0, 2,  0xFF, 0,
                                       0, 0, 7,  5, bulk_in, 2, 64, 0,    0,  7, 5, bulk_out, 2, 64, 0,    0};
        d.insert(d.end(), c.begin(), c.end());
    } else {
        std::vector<std::uint8_t> c = {9, 2, 41, 0,    1, 1,  0,    0x80, 50,   9, 4,    0,    0,
                                       2, 3, 0,  0,    0, 9,  0x21, 0x11, 0x01, 0, 1,    0x22, sizeof report_descriptor,
                                       0, 7, 5,  0x81, 3, 64, 0,    1,    7,    5, 0x01, 3,    64,
                                       0, 1};
        d.insert(d.end(), c.begin(), c.end());
    }
    return hex(d.data(), d.size());
}

// The testbed is the process's: one sysfs and /dev for every fake adapter, in a folder of the temporary
// directory ($TMPDIR) that releasing it removes.
struct Testbed {
    UMockdevTestbed* bed = umockdev_testbed_new();
    std::mutex m;
    Testbed() = default;
    Testbed(const Testbed&) = delete;
    Testbed& operator=(const Testbed&) = delete;
    ~Testbed() { g_object_unref(bed); }
    int next_devnum = 2, next_hidraw = 0;
    std::pair<int, int> numbers() {
        std::lock_guard l(m);
        int devnum = next_devnum;
        next_devnum = next_devnum >= 127 ? 2 : next_devnum + 1;
        return {devnum, next_hidraw++};
    }
};

Testbed& testbed() {
    static Testbed t;
    return t;
}

}  // namespace

const char* link_name(Link link) {
    switch (link) {
        case Link::cdc:
            return "cdc";
        case Link::usb:
            return "usb";
        case Link::hid:
            return "hid";
        case Link::pico:
            return "pico";
    }
    return "?";
}

namespace {
// The path of the loaded library whose name holds `part`, or empty.
std::string loaded_library(const char* part) {
    struct Search {
        const char* part;
        std::string path;
    } search{part, {}};
    ::dl_iterate_phdr(
        [](dl_phdr_info* info, std::size_t, void* data) {
            auto* s = static_cast<Search*>(data);
            if (!info->dlpi_name || !std::strstr(info->dlpi_name, s->part)) return 0;
            s->path = info->dlpi_name;
            return 1;
        },
        &search);
    return search.path;
}
}  // namespace

std::string umockdev_unavailable() {
    // Loaded when the program was linked with it (or started with it in LD_PRELOAD).
    if (loaded_library("libumockdev-preload").empty())
        return "umockdev's preload library is not loaded (link with -Wl,--no-as-needed -lumockdev-preload)";
    return {};
}

std::string child_preload() {
    std::string asan = loaded_library("libasan.so");
    return (asan.empty() ? "" : asan + " ") + "libumockdev-preload.so.0";
}

struct Adapter::Impl {
    Options o;
    tapesim::SimHardware hw;
    tapefw::Identity id;
    tapesim::FaultFilter filter;
    std::unique_ptr<tapefw::Engine> engine;
    std::string device;

    mutable std::mutex m;
    std::condition_variable wake, reaped;
    bool stopping = false, gone = false;
    std::deque<std::vector<std::uint8_t>> from_host;
    std::deque<std::vector<std::uint8_t>> to_host;  ///< packets, one per transfer (usb, hid)
    std::string to_host_bytes;                      ///< the byte stream (cdc)
    std::vector<std::string> unexpected;
    std::vector<std::uint8_t> punched, taken;
    std::string control_stats;
    std::size_t taken_counted = 0;
    std::uint64_t rows = 0;
    std::thread thread;

    // usb: URBs submitted on the IN endpoint and waiting for a packet, and those done and not yet reaped.
    struct Urb {
        UMockdevIoctlData* urb;
        UMockdevIoctlData* buffer;
    };
    std::deque<Urb> waiting, done;
    // hid: a read waiting for a report.
    UMockdevIoctlClient* read_waiting = nullptr;
    clock::time_point read_since{};

    std::string syspath, devnode;
    UMockdevIoctlBase* handler = nullptr;
    int master = -1, slave = -1;

    explicit Impl(Options options) : o(std::move(options)), hw(o.tape, o.sim), filter(o.faults) {
        if (o.link == Link::pico) throw std::invalid_argument("fake::Adapter does not play the emulated Pico");
        id.serial = o.serial.c_str();
        id.capabilities |= tapefw::caps::reverse | tapefw::caps::row_flags;  // SimHardware does both
        if (o.sim.control) id.capabilities |= tapefw::caps::emulate;
        hw.on_send = [this](const std::uint8_t* b, std::size_t n) {
            std::lock_guard l(m);
            if (gone) return true;  // into the void: nobody listens
            if (o.link == Link::cdc) {
                if (to_host_bytes.size() > 4096) return false;
                filter.pass(b, n, to_host_bytes);
            } else {
                if (to_host.size() >= endpoint_queue) return false;
                std::vector<std::vector<std::uint8_t>> out;
                filter.pass_packet(b, n, out);
                for (auto& packet : out) to_host.push_back(std::move(packet));
            }
            return true;
        };
        tapefw::Config defaults;
        defaults.watchdog_ms =
            static_cast<std::uint16_t>(std::min(65535.0, defaults.watchdog_ms * std::max(1.0, o.speed)));
        engine = std::make_unique<tapefw::Engine>(
            hw, id, o.link == Link::cdc ? tapefw::Framing::stream : tapefw::Framing::packets, defaults);
        if (o.link == Link::cdc)
            open_pty();
        else
            add_usb_device();
        thread = std::thread([this] { run(); });
    }

    ~Impl() {
        {
            std::lock_guard l(m);
            stopping = true;
        }
        wake.notify_all();
        thread.join();
        remove();
        if (handler) g_object_unref(handler);
    }

    void open_pty() {
        master = ::posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK);
        if (master < 0 || ::grantpt(master) != 0 || ::unlockpt(master) != 0) throw std::runtime_error("no pty");
        std::string path = ::ptsname(master);
        slave = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC);  // held: a host closing it does not hang it up
        // Not inherited by a child process (the CLI under test): unplugging must hang the line up for it too.
        ::fcntl(master, F_SETFD, FD_CLOEXEC);
        termios t{};
        ::tcgetattr(slave, &t);
        ::cfmakeraw(&t);
        ::tcsetattr(slave, TCSANOW, &t);
        device = "adapter:" + path + "?serial=" + o.serial;
    }

    // The hidraw node with its handlers, and the records of the HID device above it and its interface.
    std::string hid_device(const std::string& intf, int hidraw) {
        std::string rec;
        devnode = "/dev/hidraw" + std::to_string(hidraw);
        g_signal_connect(handler, "handle-ioctl",
                         G_CALLBACK(+[](UMockdevIoctlBase*, UMockdevIoctlClient* c, gpointer self) -> gboolean {
                             return static_cast<Impl*>(self)->hid_ioctl(c);
                         }),
                         this);
        g_signal_connect(handler, "handle-read",
                         G_CALLBACK(+[](UMockdevIoctlBase*, UMockdevIoctlClient* c, gpointer self) -> gboolean {
                             return static_cast<Impl*>(self)->hid_read(c);
                         }),
                         this);
        g_signal_connect(handler, "handle-write",
                         G_CALLBACK(+[](UMockdevIoctlBase*, UMockdevIoctlClient* c, gpointer self) -> gboolean {
                             return static_cast<Impl*>(self)->hid_write(c);
                         }),
                         this);
        std::string hid = intf + "/0003:1209:0001." + std::to_string(1000 + hidraw);
        std::string raw = "hidraw" + std::to_string(hidraw);
        rec += "P: " + hid + "/hidraw/" + raw + "\nN: " + raw + "\nE: SUBSYSTEM=hidraw\nE: DEVNAME=" + devnode +
               "\nA: dev=241:" + std::to_string(hidraw) + "\\n\nL: device=../../../" + hid.substr(hid.rfind('/') + 1) +
               "\n\n";
        rec += "P: " + hid + "\nE: SUBSYSTEM=hid\nE: DRIVER=hid-generic\nE: HID_ID=0003:00001209:00000001\n" +
               "E: HID_NAME=tape project tape adapter\nE: HID_UNIQ=" + o.serial +
               "\nH: report_descriptor=" + hex(report_descriptor, sizeof report_descriptor) + "\n\n";
        rec += "P: " + intf +
               "\nE: SUBSYSTEM=usb\nE: DEVTYPE=usb_interface\nE: DRIVER=usbhid\nA: bInterfaceNumber=00\\n\n"
               "A: bInterfaceClass=03\\n\n\n";
        return rec;
    }

    // The USB device record itself: bus numbers, ids, strings and descriptors as sysfs shows them.
    std::string usb_device_record(const std::string& usb, const char* bus_dev, int devnum) const {
        return "P: " + usb + "\nN: " + bus_dev + "\nE: SUBSYSTEM=usb\nE: DEVTYPE=usb_device\nE: DRIVER=usb\n" +
               "E: BUSNUM=001\nE: DEVNUM=" + std::string(bus_dev + 12) + "\nE: DEVNAME=/dev/" + bus_dev +
               "\nA: busnum=1\\n\nA: devnum=" + std::to_string(devnum) +
               "\\n\nA: speed=12\\n\nA: bConfigurationValue=1\\n\nA: idVendor=1209\\n\nA: idProduct=0001\\n\n" +
               "A: manufacturer=tape project\\n\nA: product=tape adapter\\n\nA: serial=" + o.serial +
               "\\n\nA: bcdDevice=0100\\n\nH: descriptors=" + descriptors(o.link) + "\n";
    }

    void add_usb_device() {
        auto [devnum, hidraw] = testbed().numbers();
        char bus_dev[32];
        std::snprintf(bus_dev, sizeof bus_dev, "bus/usb/001/%03d", devnum);
        std::string usb = "/devices/pci0000:00/0000:00:14.0/usb1/1-" + std::to_string(devnum);
        syspath = "/sys" + usb;
        handler = umockdev_ioctl_base_new();
        std::string rec;
        std::string intf = usb + "/1-" + std::to_string(devnum) + ":1.0";
        if (o.link == Link::usb) {
            devnode = std::string("/dev/") + bus_dev;
            // The vendor interface, unbound, as tape devices finds it.
            rec += "P: " + intf + "\nE: SUBSYSTEM=usb\nE: DEVTYPE=usb_interface\nA: bInterfaceNumber=00\\n\n" +
                   "A: bInterfaceClass=ff\\n\n\n";
            g_signal_connect(handler, "handle-ioctl",
                             G_CALLBACK(+[](UMockdevIoctlBase*, UMockdevIoctlClient* c, gpointer self) -> gboolean {
                                 return static_cast<Impl*>(self)->usb_ioctl(c);
                             }),
                             this);
        } else {
            rec += hid_device(intf, hidraw);
        }
        GError* error = nullptr;
        if (!umockdev_testbed_attach_ioctl(testbed().bed, devnode.c_str(), handler, &error))
            throw std::runtime_error(std::string("umockdev: ") + (error ? error->message : "cannot attach"));
        rec += usb_device_record(usb, bus_dev, devnum);
        if (!umockdev_testbed_add_from_string(testbed().bed, rec.c_str(), &error))
            throw std::runtime_error(std::string("umockdev: ") + (error ? error->message : "cannot add"));
        if (o.link == Link::hid) {
            // The node is umockdev's pseudo-terminal: a byte in it makes poll() say "readable" for good, and
            // every read() then comes to hid_read, which waits for a report as hidraw does.
            int fd = umockdev_testbed_get_dev_fd(testbed().bed, devnode.c_str());
            char ready = 0;
            if (fd < 0 || ::write(fd, &ready, 1) != 1) throw std::runtime_error("umockdev: no pty behind " + devnode);
        }
        device = std::string(link_name(o.link)) + ":1209:0001?serial=" + o.serial;
    }

    void remove() {
        if (master >= 0) {
            ::close(master);
            ::close(slave);
            master = slave = -1;
        }
        if (syspath.empty()) return;
        umockdev_testbed_uevent(testbed().bed, syspath.c_str(), "remove");
        umockdev_testbed_remove_device(testbed().bed, syspath.c_str());
        umockdev_testbed_detach_ioctl(testbed().bed, devnode.c_str(), nullptr);
        syspath.clear();
    }

    void note(const std::string& what) {
        std::lock_guard l(m);
        unexpected.push_back(what);
    }

    // ---- the device's own loop: the firmware's main loop, on the simulated clock.

    void run() {
        const auto t0 = clock::now();
        const std::uint64_t step = static_cast<std::uint64_t>(16e6 / o.sim.read_rate);
        for (;;) {
            std::deque<std::vector<std::uint8_t>> in;
            {
                std::lock_guard l(m);
                if (stopping) return;
                in.swap(from_host);
            }
            if (master >= 0) read_pty(in);
            bool up = !is_gone();
            if (up)
                for (auto& b : in) engine->receive(b.data(), b.size());
            auto target =
                static_cast<std::uint64_t>(std::chrono::duration<double>(clock::now() - t0).count() * o.speed * 1e6);
            while (hw.now() < target) {
                hw.advance_to(std::min(target, hw.now() + step), *engine);
                engine->poll();
            }
            engine->poll();
            {
                std::lock_guard l(m);
                rows = engine->rows_read();
                // Only the rows punched since: the whole run is not copied at every turn.
                punched.insert(punched.end(), hw.punched().begin() + static_cast<long>(punched.size()),
                               hw.punched().end());
                if (const auto* c = hw.control()) {
                    taken.insert(taken.end(), c->taken().begin() + static_cast<long>(taken.size()), c->taken().end());
                    if (c->taken().size() != taken_counted) control_stats = c->stats_json();
                    taken_counted = c->taken().size();
                }
            }
            if (up && o.unplug_after && std::max(engine->rows_read(), engine->frames_taken()) >= o.unplug_after)
                unplug();
            deliver();
            std::unique_lock l(m);
            wake.wait_for(l, 300us, [this] { return stopping || !from_host.empty(); });
        }
    }

    bool is_gone() const {
        std::lock_guard l(m);
        return gone;
    }

    void read_pty(std::deque<std::vector<std::uint8_t>>& in) {
        std::uint8_t buf[4096];
        ssize_t n;
        while ((n = ::read(master, buf, sizeof buf)) > 0) in.emplace_back(buf, buf + n);
    }

    void deliver() {
        std::lock_guard l(m);
        if (gone) return;
        if (o.link == Link::cdc) {
            while (!to_host_bytes.empty()) {
                ssize_t n = ::write(master, to_host_bytes.data(), to_host_bytes.size());
                if (n <= 0) break;
                to_host_bytes.erase(0, static_cast<std::size_t>(n));
            }
        } else if (o.link == Link::usb) {
            while (!waiting.empty() && !to_host.empty()) {
                fill(waiting.front(), to_host.front());
                to_host.pop_front();
                done.push_back(waiting.front());
                waiting.pop_front();
                reaped.notify_all();
            }
        } else if (read_waiting) {
            if (!to_host.empty()) {
                answer_read(read_waiting, to_host.front());
                to_host.pop_front();
            } else if (clock::now() - read_since >= hid_read_wait) {
                umockdev_ioctl_client_complete(read_waiting, -1, EAGAIN);
            } else {
                return;
            }
            g_object_unref(read_waiting);
            read_waiting = nullptr;
        }
    }

    void unplug() {
        std::lock_guard l(m);
        if (gone) return;
        gone = true;
        // What the kernel does: URBs in flight end, a waiting read fails, the line hangs up.
        for (auto& u : waiting) {
            auto* urb = reinterpret_cast<usbdevfs_urb*>(u.urb->data);
            urb->status = -ESHUTDOWN;
            urb->actual_length = 0;
            done.push_back(u);
        }
        waiting.clear();
        reaped.notify_all();
        if (read_waiting) {
            umockdev_ioctl_client_complete(read_waiting, -1, EIO);
            g_object_unref(read_waiting);
            read_waiting = nullptr;
        }
        if (master >= 0) {
            ::close(master);
            ::close(slave);
            master = slave = -1;
        }
    }

    // ---- usbfs, as the kernel answers it (on umockdev's thread).

    static void fill(const Urb& u, const std::vector<std::uint8_t>& packet) {
        auto* urb = reinterpret_cast<usbdevfs_urb*>(u.urb->data);
        std::size_t n = std::min<std::size_t>(packet.size(), static_cast<std::size_t>(urb->buffer_length));
        std::memcpy(u.buffer->data, packet.data(), n);
        urb->actual_length = static_cast<int>(n);
        urb->status = 0;
    }

    bool usb_ioctl(UMockdevIoctlClient* client) {
        unsigned long request = umockdev_ioctl_client_get_request(client);
        UMockdevIoctlData* arg = umockdev_ioctl_client_get_arg(client);
        std::unique_lock l(m);
        if (gone && request != USBDEVFS_REAPURBNDELAY && request != USBDEVFS_REAPURB) {
            umockdev_ioctl_client_complete(client, -1, ENODEV);
            return true;
        }
        switch (request) {
            case USBDEVFS_GET_CAPABILITIES: {
                UMockdevIoctlData* caps = umockdev_ioctl_data_resolve(arg, 0, sizeof(std::uint32_t), nullptr);
                *reinterpret_cast<std::uint32_t*>(caps->data) = USBDEVFS_CAP_BULK_CONTINUATION |
                                                                USBDEVFS_CAP_NO_PACKET_SIZE_LIM |
                                                                USBDEVFS_CAP_REAP_AFTER_DISCONNECT;
                umockdev_ioctl_client_complete(client, 0, 0);
                g_object_unref(caps);
                return true;
            }
            case USBDEVFS_IOCTL:  // the kernel's driver taken off the interface, or given it back
            case USBDEVFS_CLAIMINTERFACE:
            case USBDEVFS_RELEASEINTERFACE:
            case USBDEVFS_DISCONNECT_CLAIM:
            case USBDEVFS_CLEAR_HALT:
                umockdev_ioctl_client_complete(client, 0, 0);
                return true;
            case USBDEVFS_SUBMITURB:
                return submit(client, arg);
            case USBDEVFS_REAPURB:
            case USBDEVFS_REAPURBNDELAY:
                return reap(client, arg, l);
            case USBDEVFS_DISCARDURB:
                return discard(client, arg);
            default:
                l.unlock();
                note("usbfs ioctl " + std::to_string(request));
                umockdev_ioctl_client_complete(client, -1, ENOTTY);
                return true;
        }
    }

    // Called with m held (l): the oldest finished URB, waiting a while for one.
    bool reap(UMockdevIoctlClient* client, UMockdevIoctlData* arg, std::unique_lock<std::mutex>& l) {
        if (done.empty() && !gone) reaped.wait_for(l, reap_wait);
        if (done.empty()) {
            umockdev_ioctl_client_complete(client, -1, gone ? ENODEV : EAGAIN);
            return true;
        }
        Urb u = done.front();
        done.pop_front();
        UMockdevIoctlData* where = umockdev_ioctl_data_resolve(arg, 0, sizeof(void*), nullptr);
        umockdev_ioctl_data_set_ptr(where, 0, u.urb);
        umockdev_ioctl_client_complete(client, 0, 0);
        g_object_unref(where);
        g_object_unref(u.urb);
        return true;
    }

    // Called with m held: a URB the host gives up on, finished as cancelled if it still waits.
    bool discard(UMockdevIoctlClient* client, UMockdevIoctlData* arg) {
        void* which = *reinterpret_cast<void**>(arg->data);
        for (auto it = waiting.begin(); it != waiting.end(); ++it) {
            if (reinterpret_cast<void*>(it->urb->client_addr) != which) continue;
            auto* urb = reinterpret_cast<usbdevfs_urb*>(it->urb->data);
            urb->status = -ENOENT;
            urb->actual_length = 0;
            done.push_back(*it);
            waiting.erase(it);
            reaped.notify_all();
            umockdev_ioctl_client_complete(client, 0, 0);
            return true;
        }
        umockdev_ioctl_client_complete(client, -1, EINVAL);  // done already: the host reaps it
        return true;
    }

    // Called with m held.
    bool submit(UMockdevIoctlClient* client, UMockdevIoctlData* arg) {
        UMockdevIoctlData* data = umockdev_ioctl_data_resolve(arg, 0, sizeof(usbdevfs_urb), nullptr);
        auto* urb = reinterpret_cast<usbdevfs_urb*>(data->data);
        UMockdevIoctlData* buffer = umockdev_ioctl_data_resolve(data, offsetof(usbdevfs_urb, buffer),
                                                                static_cast<std::size_t>(urb->buffer_length), nullptr);
        Urb u{data, buffer};
        if (urb->type == USBDEVFS_URB_TYPE_CONTROL && buffer) {
            control(urb, buffer->data);
            done.push_back(u);
        } else if (urb->type == USBDEVFS_URB_TYPE_BULK && urb->endpoint == bulk_out && buffer) {
            from_host.emplace_back(buffer->data, buffer->data + urb->buffer_length);
            urb->actual_length = urb->buffer_length;
            urb->status = 0;
            done.push_back(u);
            wake.notify_all();
        } else if (urb->type == USBDEVFS_URB_TYPE_BULK && urb->endpoint == bulk_in && buffer) {
            if (!to_host.empty()) {
                fill(u, to_host.front());
                to_host.pop_front();
                done.push_back(u);
            } else {
                waiting.push_back(u);
            }
        } else {
            unexpected.push_back("URB of type " + std::to_string(urb->type) + " on endpoint " +
                                 std::to_string(urb->endpoint));
            umockdev_ioctl_client_complete(client, -1, EINVAL);
            g_object_unref(data);
            return true;
        }
        reaped.notify_all();
        umockdev_ioctl_client_complete(client, 0, 0);
        return true;
    }

    // GET_DESCRIPTOR of a string: the only control request a host has reason to make of the adapter.
    void control(usbdevfs_urb* urb, std::uint8_t* buffer) {
        const std::uint8_t* setup = buffer;
        unsigned length = setup[6] | (setup[7] << 8u);
        std::vector<std::uint8_t> reply;
        if (setup[0] == 0x80 && setup[1] == 6 && setup[3] == 3) {
            std::string text = setup[2] == 1 ? "tape project" : setup[2] == 2 ? "tape adapter" : o.serial;
            if (setup[2] == 0) {
                reply = {4, 3, 0x09, 0x04};
            } else {
                reply = {static_cast<std::uint8_t>(2 + 2 * text.size()), 3};
                for (char c : text) reply.insert(reply.end(), {static_cast<std::uint8_t>(c), 0});
            }
            std::size_t n = std::min<std::size_t>(reply.size(), length);
            std::memcpy(buffer + 8, reply.data(), n);
            urb->actual_length = static_cast<int>(n);
            urb->status = 0;
            return;
        }
        unexpected.push_back("control request " + hex(setup, 8));
        urb->actual_length = 0;
        urb->status = -EPIPE;  // a stall, as the adapter answers what it does not know
    }

    // ---- hidraw, as the kernel answers it.

    bool hid_ioctl(UMockdevIoctlClient* client) {
        unsigned long request = umockdev_ioctl_client_get_request(client);
        UMockdevIoctlData* arg = umockdev_ioctl_client_get_arg(client);
        if (is_gone()) {
            umockdev_ioctl_client_complete(client, -1, ENODEV);
            return true;
        }
        if (request == HIDIOCGRDESCSIZE) {
            UMockdevIoctlData* size = umockdev_ioctl_data_resolve(arg, 0, sizeof(int), nullptr);
            *reinterpret_cast<int*>(size->data) = sizeof report_descriptor;
            umockdev_ioctl_client_complete(client, 0, 0);
            g_object_unref(size);
            return true;
        }
        if (request == HIDIOCGRDESC) {
            UMockdevIoctlData* d = umockdev_ioctl_data_resolve(arg, 0, sizeof(hidraw_report_descriptor), nullptr);
            auto* desc = reinterpret_cast<hidraw_report_descriptor*>(d->data);
            desc->size = sizeof report_descriptor;
            std::memcpy(desc->value, report_descriptor, sizeof report_descriptor);
            umockdev_ioctl_client_complete(client, 0, 0);
            g_object_unref(d);
            return true;
        }
        note("hidraw ioctl " + std::to_string(request));
        umockdev_ioctl_client_complete(client, -1, EINVAL);
        return true;
    }

    static void answer_read(UMockdevIoctlClient* client, const std::vector<std::uint8_t>& packet) {
        UMockdevIoctlData* arg = umockdev_ioctl_client_get_arg(client);
        // A report is 64 bytes, the packet padded with zeros.
        std::size_t n = std::min<std::size_t>(tapefw::report_size, static_cast<std::size_t>(arg->data_len));
        std::memset(arg->data, 0, n);
        std::memcpy(arg->data, packet.data(), std::min(n, packet.size()));
        umockdev_ioctl_client_complete(client, static_cast<glong>(n), 0);
    }

    bool hid_read(UMockdevIoctlClient* client) {
        std::lock_guard l(m);
        if (gone) {
            umockdev_ioctl_client_complete(client, -1, EIO);
            return true;
        }
        if (!to_host.empty()) {
            answer_read(client, to_host.front());
            to_host.pop_front();
            return true;
        }
        // Waits, as a blocking read of hidraw does, until a report comes (or, here, a short while).
        read_waiting = static_cast<UMockdevIoctlClient*>(g_object_ref(client));
        read_since = clock::now();
        return true;
    }

    bool hid_write(UMockdevIoctlClient* client) {
        UMockdevIoctlData* arg = umockdev_ioctl_client_get_arg(client);
        std::lock_guard l(m);
        if (gone) {
            umockdev_ioctl_client_complete(client, -1, ENODEV);
            return true;
        }
        int n = arg->data_len;
        // The first byte is the report id: 0, the adapter's reports are not numbered.
        if (n != 1 + static_cast<int>(tapefw::report_size) || arg->data[0] != 0) {
            unexpected.push_back("HID write of " + std::to_string(n) + " bytes, report id " +
                                 std::to_string(n > 0 ? arg->data[0] : -1));
            umockdev_ioctl_client_complete(client, -1, EINVAL);
            return true;
        }
        from_host.emplace_back(arg->data + 1, arg->data + n);
        wake.notify_all();
        umockdev_ioctl_client_complete(client, n, 0);
        return true;
    }
};

Adapter::Adapter(Options options) : impl_(std::make_unique<Impl>(std::move(options))) {}
Adapter::~Adapter() = default;

const std::string& Adapter::device() const { return impl_->device; }
void Adapter::unplug() { impl_->unplug(); }

std::vector<std::uint8_t> Adapter::punched() const {
    std::lock_guard l(impl_->m);
    return impl_->punched;
}

std::vector<std::uint8_t> Adapter::control_taken() const {
    std::lock_guard l(impl_->m);
    return impl_->taken;
}

std::string Adapter::control_stats() const {
    std::lock_guard l(impl_->m);
    return impl_->control_stats;
}

std::uint64_t Adapter::rows_read() const {
    std::lock_guard l(impl_->m);
    return impl_->rows;
}

std::vector<std::string> Adapter::unexpected() const {
    std::lock_guard l(impl_->m);
    return impl_->unexpected;
}

void Adapter::send_garbage() {
    std::lock_guard l(impl_->m);
    // Noise: bytes that decode to no packet; on a stream, ended by a zero as a line glitch would be.
    std::vector<std::uint8_t> noise = {0x55, 0xAA, 0x13, 0x7F, 0x42, 0x99, 0x01, 0xFE, 0x33, 0x21};
    if (impl_->o.link == Link::cdc) {
        impl_->to_host_bytes.append(reinterpret_cast<const char*>(noise.data()), noise.size());
        impl_->to_host_bytes.push_back('\0');
    } else {
        impl_->to_host.push_front(noise);
    }
}

}  // namespace fake
