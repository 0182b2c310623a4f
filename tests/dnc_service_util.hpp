// A tape dnc service run as a real process over pseudo-terminals, with the controls played by the
// test: shared by the DNC tests.
#pragma once

#include <sys/stat.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "process_util.hpp"
#include "pty_util.hpp"
#include "tape/code.hpp"
#include "tape/line_state.hpp"
#include "test_util.hpp"

/// A control on the far end of a pseudo-terminal: punches out ISO text with even parity, takes what
/// the service sends.
struct Control {
    Pty pty;

    /// The frames of text as an ISO tape with even parity.
    static std::vector<std::uint8_t> iso(std::string_view text) {
        static const tape::FrameCode code = tape::FrameCode::iso();
        std::vector<std::uint8_t> out;
        for (char c : text) out.push_back(code.frame_for(static_cast<unsigned char>(c)).value_or(0));
        return out;
    }
    void punch(std::string_view text) const { punch_on(pty, text); }
    static void punch_on(const Pty& pty, std::string_view text) {
        auto bytes = iso(text);
        if (::write(pty.master, bytes.data(), bytes.size()) != static_cast<ssize_t>(bytes.size()))
            throw std::runtime_error("pty write failed");
    }
    /// What arrives until the line is quiet for `quiet`, as text (track 8, blank tape and DEL dropped).
    std::string receive_text(std::chrono::milliseconds quiet, std::chrono::milliseconds limit) const {
        std::vector<std::uint8_t> got;
        pty.receive_until_quiet(got, quiet, limit);
        return text_of(got);
    }
    static std::string text_of(const std::vector<std::uint8_t>& frames) {
        std::string text;
        for (auto b : frames)
            if ((b & 0x7F) != 0 && (b & 0x7F) != 0x7F) text += static_cast<char>(b & 0x7F);
        return text;
    }
};

/// A library, a received folder, a runtime folder and n controls; the service started on them.
struct DncRun {
    TempDir dir;
    std::vector<std::unique_ptr<Control>> controls;
    std::unique_ptr<Process> service;

    explicit DncRun(std::size_t machines) {
        for (auto sub : {"programs", "received", "run"}) std::filesystem::create_directory(dir.file(sub));
        ::chmod(dir.file("run").c_str(), 0700);  // a runtime folder open to others is refused
        for (std::size_t i = 0; i < machines; ++i) controls.push_back(std::make_unique<Control>());
    }
    bool ok() const { return controls.empty() || controls[0]->pty.ok(); }
    std::string programs() const { return dir.file("programs"); }
    std::string received() const { return dir.file("received"); }
    std::string config() const { return dir.file("dnc.toml"); }

    void add_program(const std::string& name, const std::string& text) const {
        std::ofstream(programs() + "/" + name) << text;
    }
    /// The config with machine i as "m<i>" on its pty; `extra` lines go into every [[machine]].
    void write_config(const std::string& extra = "", const std::string& settings = "baud=9600&flow=xonxoff",
                      const std::vector<std::string>& per_machine = {}) const {
        std::ofstream out(config());
        out << "[library]\nprograms = \"" << programs() << "\"\nreceived = \"" << received() << "\"\n"
            << "[service]\nruntime_directory = \"" << dir.file("run") << "\"\n";
        for (std::size_t i = 0; i < controls.size(); ++i)
            out << "[[machine]]\nname = \"m" << i << "\"\ndevice = \"" << controls[i]->pty.device(settings)
                << "\"\nleader = 4\ntrailer = 4\nreceive_timeout = 2\n"
                << extra << "\n"
                << (i < per_machine.size() ? per_machine[i] + "\n" : "");
    }
    /// Starts tape dnc and waits until it says it serves.
    bool start() {
        service = std::make_unique<Process>(std::vector<std::string>{"dnc", "--config", config()}, dir);
        return wait_log("serving", std::chrono::seconds(10));
    }
    std::string log() const { return read_text(dir.file("stderr")); }
    bool wait_log(const std::string& what, std::chrono::milliseconds limit, std::size_t times = 1) const {
        auto end = std::chrono::steady_clock::now() + limit;
        while (std::chrono::steady_clock::now() < end) {
            std::string l = log();
            std::size_t n = 0;
            for (auto at = l.find(what); at != std::string::npos; at = l.find(what, at + 1)) ++n;
            if (n >= times) return true;
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        return false;
    }
    /// The name of the file in received/ that came to hold text within limit ("" if none did): what a
    /// control punched is on disk as it arrives.
    std::string wait_received(const std::string& text, std::chrono::milliseconds limit) const {
        std::string name;
        eventually(
            [&] {
                for (const auto& f : received_files())
                    if (read_text(received() + "/" + f) == text) name = f;
                return !name.empty();
            },
            limit);
        return name;
    }
    /// How many times what stands in the log.
    std::size_t log_count(const std::string& what) const {
        std::string l = log();
        std::size_t n = 0;
        for (auto at = l.find(what); at != std::string::npos; at = l.find(what, at + 1)) ++n;
        return n;
    }
    std::vector<std::string> received_files() const {
        std::vector<std::string> names;
        for (const auto& e : std::filesystem::directory_iterator(received())) names.push_back(e.path().filename());
        std::sort(names.begin(), names.end());
        return names;
    }
};

#ifdef TAPE_WITH_TOML
#define DNC_OR_SKIP(run) \
    if (!(run).ok()) GTEST_SKIP() << "no pseudo-terminal here: " << (run).controls[0]->pty.error
#else
#define DNC_OR_SKIP(run) GTEST_SKIP() << "tape was built without toml++: tape dnc cannot read a config"
#endif
