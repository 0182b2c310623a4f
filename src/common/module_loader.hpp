// Loading an optional part of tape (a shared object with one table of functions) on first use, so that a
// command that does not need its libraries does not map them: the picture module (OpenCV) and the plot
// module (cairo). Looked for beside the program (../RELATIVE, as in the build tree and any prefix it was
// installed to), then where it was configured to be installed; an environment variable names another file.
#pragma once

#include <string>

namespace tape::modules {

struct ModuleSpec {
    const char* what;       ///< "the picture module, which reads and writes pictures through OpenCV"
    const char* env;        ///< "TAPE_PICTURE_MODULE": a file to load instead
    const char* relative;   ///< from the program's folder's parent: "lib/tape/tape-pictures.so"
    const char* installed;  ///< the absolute path it was configured to be installed to
    const char* symbol;     ///< the one exported function returning the table
    const char* needs;      ///< said when it does not load: "it needs OpenCV's ... (Debian: ...)"
};

struct Opened {
    const void* table = nullptr;  ///< what symbol returned; nullptr when not loaded
    std::string why{};            ///< empty when table is there
    std::string path{};           ///< the file loaded
};

/// Opens the module (never closed: its functions serve until the program ends) and calls its symbol.
/// The caller checks the table's ABI version.
Opened open_module(const ModuleSpec& spec);

}  // namespace tape::modules
