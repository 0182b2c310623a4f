// Contract test over the device table: every backend, the ones added later included, keeps what
// include/tape/device.hpp promises. A backend that can be opened here (file:, serial: on a
// pseudo-terminal) also carries every byte value both ways.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <numeric>

#include "pty_util.hpp"
#include "tape/device.hpp"
#include "tape/error.hpp"
#include "test_util.hpp"

using namespace tape;
using namespace std::chrono_literals;

namespace {

std::vector<std::string> backend_prefixes() {
    std::vector<std::string> prefixes;
    for (const auto& b : device_backends()) prefixes.emplace_back(b.prefix);
    return prefixes;
}

const DeviceBackend& backend(const std::string& prefix) {
    for (const auto& b : device_backends())
        if (b.prefix == prefix) return b;
    throw std::logic_error("no backend " + prefix);
}

std::vector<std::uint8_t> every_byte_value() {
    std::vector<std::uint8_t> bytes(256);
    std::iota(bytes.begin(), bytes.end(), 0);
    return bytes;
}

/// Reads from line until `size` bytes came, the line ended, or `limit` passed.
std::vector<std::uint8_t> read_all(Transport& line, std::size_t size, std::chrono::milliseconds limit) {
    std::vector<std::uint8_t> got;
    std::uint8_t buf[100];
    auto deadline = std::chrono::steady_clock::now() + limit;
    while (got.size() < size && std::chrono::steady_clock::now() < deadline) {
        ReadResult r = line.read(buf, 50ms);
        got.insert(got.end(), buf, buf + r.count);
        if (r.end) break;
    }
    return got;
}

class DeviceBackendContract : public ::testing::TestWithParam<std::string> {};

}  // namespace

TEST_P(DeviceBackendContract, DescribesItselfInTheTable) {
    const DeviceBackend& b = backend(GetParam());
    EXPECT_FALSE(b.prefix.empty());
    EXPECT_EQ(b.prefix.find(':'), std::string_view::npos) << b.prefix;
    EXPECT_FALSE(b.description.empty());
    EXPECT_TRUE(b.syntax.starts_with(std::string(b.prefix) + ":")) << b.syntax;
    EXPECT_NE(b.open, nullptr);
    auto prefixes = backend_prefixes();
    EXPECT_EQ(std::count(prefixes.begin(), prefixes.end(), GetParam()), 1) << "a prefix chooses one backend";
}

// Whatever it is opened for, a device that is not there is an I/O or usage error naming the device.
TEST_P(DeviceBackendContract, ABadPathFailsNamingTheDevice) {
    TempDir dir;
    std::string device = GetParam() + ":" + dir.file("no-such-folder/no-such-device");
    for (DeviceUse use : {DeviceUse::read, DeviceUse::write, DeviceUse::both}) {
        SCOPED_TRACE(static_cast<int>(use));
        try {
            open_device(device, use);
            ADD_FAILURE() << device << " opened";
        } catch (const Error& e) {
            EXPECT_TRUE(e.code() == Errc::io || e.code() == Errc::usage) << errc_name(e.code());
            EXPECT_NE(std::string(e.what()).find(device), std::string::npos) << e.what();
        }
    }
    EXPECT_TRUE(std::filesystem::is_empty(dir.path)) << "a failed open left something behind";
}

// A setting the backend does not know is refused by name, before anything is opened.
TEST_P(DeviceBackendContract, AnUnknownSettingIsAUsageErrorNamingIt) {
    TempDir dir;
    std::string device = GetParam() + ":" + dir.file("device") + "?no-such-setting=1";
    try {
        open_device(device, DeviceUse::write);
        ADD_FAILURE() << device << " opened";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), Errc::usage) << e.what();
        EXPECT_NE(std::string(e.what()).find("'no-such-setting'"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(std::filesystem::is_empty(dir.path)) << "a refused device string created something";
}

// Every backend carries every byte value out and back unchanged, and a test shows it: here for the
// backends that can be opened in a test (a file, a pseudo-terminal), in adapter_backends_test for the tape
// adapters (reading and punching through adapter:, usb: and hid: against the firmware core: writing to an
// adapter punches, and reading reads the tape in its reader). A backend added to the table needs one.
const std::vector<std::string> round_trip_here = {"file", "serial"};
const std::vector<std::string> round_trip_in_adapter_suite = {"adapter", "usb", "hid"};

TEST_P(DeviceBackendContract, HasATestCarryingEveryByteValue) {
    auto in = [&](const std::vector<std::string>& list) {
        return std::find(list.begin(), list.end(), GetParam()) != list.end();
    };
    EXPECT_TRUE(in(round_trip_here) || in(round_trip_in_adapter_suite))
        << GetParam() << ": no test writes and reads back every byte value through it";
}

TEST(FileDevice, WriteThenReadGivesTheSameBytes) {
    const auto bytes = every_byte_value();
    TempDir dir;
    std::string device = "file:" + dir.file("tape.ptp");
    {
        auto out = open_device(device, DeviceUse::write);
        out->write(bytes);
        out->drain();
    }
    auto in = open_device(device, DeviceUse::read);
    EXPECT_EQ(read_all(*in, bytes.size() + 1, 5s), bytes);
}

TEST(SerialDevice, WriteThenReadGivesTheSameBytes) {
    const auto bytes = every_byte_value();
    PTY_OR_SKIP(pty);
    // 8N1 without flow control: DC1 and DC3 are data here, and bit 8 passes.
    auto line = open_device(pty.device("baud=115200&bits=8&parity=none&flow=none"), DeviceUse::both);
    line->write(bytes);
    line->drain();
    std::vector<std::uint8_t> out;
    pty.receive_until_size(out, bytes.size(), 5s);
    EXPECT_EQ(out, bytes);
    ASSERT_EQ(::write(pty.master, bytes.data(), bytes.size()), static_cast<ssize_t>(bytes.size()));
    EXPECT_EQ(read_all(*line, bytes.size(), 5s), bytes);
}

INSTANTIATE_TEST_SUITE_P(EveryBackend, DeviceBackendContract, ::testing::ValuesIn(backend_prefixes()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             std::string name = info.param;
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return name;
                         });
