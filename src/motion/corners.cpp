// Fanuc's corner words after a move: ",C" (a chamfer) and ",R" (a rounding) join it to the next move.
// The corner lies between this block and the next, which a streaming interpreter has not read yet: the
// moves are drawn to the sharp corner and the block says so. Where the next move ends is the same.
#include "motion/machine.hpp"

namespace tape {

void MotionMachine::corner_words(const Block& b) {
    for (const auto& w : b.words) {
        if (w.address != ',') continue;
        bool chamfer = w.text.find_first_of("Cc") != std::string::npos;
        not_simulated(w.text + " (" + (chamfer ? "a chamfer" : "a rounding") +
                          " of the corner to the next move) is not drawn: the moves are drawn to the sharp corner",
                      0);
        return;
    }
}

}  // namespace tape
