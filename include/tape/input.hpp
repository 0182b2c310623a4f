// Opening whatever the user gave: a tape image or a text program, from a file, standard input or any
// byte source, read a chunk at a time in bounded memory:
//     bytes -> image format -> frames -> detected code -> text -> programs.
// The one entry point commands and programs use; nothing here prints or exits.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "tape/decode.hpp"
#include "tape/detect.hpp"
#include "tape/file_io.hpp"
#include "tape/image.hpp"
#include "tape/image_input.hpp"
#include "tape/label.hpp"
#include "tape/program.hpp"
#include "tape/restore_doubts.hpp"
#include "tape/utf8_text.hpp"

namespace tape {

enum class InputKind {
    automatic,  ///< an image by format, extension or content; clean UTF-8 text is a text program
    text,       ///< a text program
    image,      ///< a tape image
};

struct InputOptions {
    InputKind kind = InputKind::automatic;
    const ImageFormat* format = nullptr;  ///< given: the input is an image in this format
    bool detect_code = true;              ///< decide ISO or EIA from the tape (ISO when decode.parity is not even)
    DecodeOptions decode{};               ///< the code when not detected, parity, charset, positions, limits
    /// Also give the runs a restoration decided against a read (its doubts file lists them), each as a
    /// note where it stands: they are not in doubt, but a wrong length could hide there.
    bool decided_runs = false;
};

class Input {
public:
    /// Opens path ("-": standard input). Throws Error(Errc::io) when it cannot be read.
    Input(const std::string& path, const InputOptions& options);
    /// The same over any source; name is used for its extension only.
    Input(std::unique_ptr<ByteSource> source, const std::string& name, const InputOptions& options);
    ~Input();
    Input(const Input&) = delete;
    Input& operator=(const Input&) = delete;

    bool is_image() const { return image_ != nullptr; }
    /// The image's format, or nullptr for a text program.
    const ImageFormat* format() const { return image_ ? &image_->format() : nullptr; }

    /// An image's frames, a chunk at a time, valid until the next call; empty at the end. A leader
    /// label's frames are given as they are (they are holes on the tape).
    std::span<const Frame> next_frames();

    /// The label in an image's leader (tape/label.hpp), looked for before the first frames are given;
    /// nullopt for none, for a text program, or once frames were given. next_text() and the code's
    /// detection read its frames as blank tape, so the program and its text are the same with or without it.
    std::optional<LeaderLabel> label();

    /// How an image is decoded: decided on first use, detecting the code when asked (the frames read
    /// for it are given again); a code the image's header names is taken unless it is ISO, whose parity
    /// the header does not say. Throws Error(Errc::unknown_code), with the verdict, when the tape is
    /// neither ISO nor EIA (another parity, 5-track, binary, a text file).
    const DecodeOptions& decode_options();
    /// The code an image's header names (tape/image_input.hpp); nullopt for none and for a text program.
    std::optional<Code> declared_code();
    /// How the code was detected, once it was.
    const std::optional<CodeDetection>& detection() const { return detection_; }
    /// The verdict on an image (detect_code) from a read-ahead of its start, the whole of most tapes
    /// (given again by next_frames), even when the options did not ask for it; never throws for a
    /// tape that fits no code.
    const CodeDetection& detect();

    /// The next piece of program text, appended to out: an image decoded (frame_of counted from the
    /// start of the tape when decode.positions; out.diagnostics for bad frames), a text program as it
    /// is. False at the end, or once decoding stopped at a bad frame (out.complete is then false).
    /// A text program that is not clean UTF-8 throws Error(Errc::bad_text) at the byte.
    bool next_text(DecodeResult& out);
    /// What was noticed on the way that is not wrong (a skipped byte-order mark, a text ending with DOS
    /// end-of-file marks), for the caller to say: those known once the input is opened are there then.
    const std::vector<Diagnostic>& notes() const { return notes_; }
    /// The decoder of an image, for the counts of bad frames; nullptr before next_text or for text.
    const Decoder* decoder() const { return decoder_.get(); }
    /// Frames in doubt met so far: an image file restored by tape restore, whose doubts file beside it
    /// (tape/restore_doubts.hpp) names frames its restoration could not decide. Each is given by
    /// next_text as a Diagnostic (Errc::doubtful_frame) where it stands, and stops decoding as a bad
    /// frame does (unless decode.keep_going). Entries of the doubts file that cannot be read are warnings
    /// among the notes.
    std::uint64_t doubtful_frames() const { return doubtful_met_; }
    /// True when no code fits the tape and, with decode.keep_going, it is decoded with the closest reading
    /// (CodeDetection::closest): the caller must say so (closest_reading_note).
    bool closest_taken() const { return closest_taken_; }

private:
    void open(std::unique_ptr<ByteSource> source, const std::string& name);
    void read_doubts(const std::string& path);
    bool feed_with_doubts(std::span<const Frame> frames, std::uint64_t first, DecodeResult& out);

    InputOptions options_;
    std::unique_ptr<ImageInput> image_;
    std::unique_ptr<ByteSource> text_source_;
    std::vector<std::uint8_t> text_ahead_;  // what the choice of image or text looked at
    std::unique_ptr<std::uint8_t[]> text_buffer_;
    TextChecker text_checker_;
    std::optional<DecodeOptions> decode_;
    std::optional<CodeDetection> detection_;
    std::unique_ptr<Decoder> decoder_;
    std::vector<Diagnostic> notes_;
    bool ended_ = false;
    bool mark_noted_ = false;            // the DOS end-of-file mark was noted when the text was opened
    std::uint64_t decoded_frames_ = 0;   // frames given to the decoder: where the next chunk starts
    std::vector<Frame> unlabelled_;      // a chunk with the label's frames blanked
    std::vector<DoubtfulFrame> doubts_;  // from the doubts file beside the image, by frame
    std::size_t next_doubt_ = 0;
    std::uint64_t doubtful_met_ = 0;
    bool closest_taken_ = false;
};

/// Streams the programs of input into visitor, in bounded memory. A bad frame reaches
/// visitor.finding() as its Diagnostic (Errc::parity, Errc::not_in_code) where it stands among the
/// loader's findings; unless decode.keep_going, loading stops there and false is returned.
bool load_each(Input& input, ProgramVisitor& visitor, const LoadOptions& options = {});

/// The whole contents in memory, for the commands that need all of it at once; bad frames are
/// among tape.findings. Returns false with what was loaded when a bad frame stopped decoding.
bool load(Input& input, LoadedTape& tape, const LoadOptions& options = {});

}  // namespace tape
