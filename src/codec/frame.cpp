#include "tape/frame.hpp"

namespace tape {

std::string holes_picture(Frame f) {
    std::string s = "|     .   |";
    static constexpr int column_of_track[9] = {0, 9, 8, 7, 5, 4, 3, 2, 1};
    for (int track = 1; track <= 8; ++track)
        if (has_track(f, track)) s[column_of_track[track]] = 'o';
    return s;
}

}  // namespace tape
