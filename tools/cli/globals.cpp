#include "cli/globals.hpp"

#include "cli/files.hpp"
#include "cli/messages.hpp"
#include "tape/file_io.hpp"

namespace cli {

Globals& globals() {
    static Globals g;
    return g;
}

const tape::CodeTable* Globals::table() {
    if (eia_table.empty()) return nullptr;
    if (!loaded_table) {
        note_input(eia_table);
        try {
            // A code table is a page of text: anything much bigger is not one (/dev/zero, a tape image).
            auto bytes = tape::read_file(eia_table, max_table_bytes, tape::Errc::bad_table);
            loaded_table =
                tape::CodeTable::parse(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
        } catch (const tape::Error& e) {
            fail(eia_table, e);
        }
    }
    return &*loaded_table;
}

}  // namespace cli
