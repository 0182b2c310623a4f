#include "tape/frame.hpp"

namespace tape {

std::string holes_picture(Frame f) {
    std::string s = "|     .   |";
    static constexpr int column_of_track[9] = {0, 9, 8, 7, 5, 4, 3, 2, 1};
    for (int track = 1; track <= 8; ++track)
        if (has_track(f, track)) s[column_of_track[track]] = 'o';
    return s;
}

std::span<const Frame> punched_part(std::span<const Frame> frames) {
    std::size_t a = 0, b = frames.size();
    while (a < b && frames[a] == blank_frame) ++a;
    while (b > a && frames[b - 1] == blank_frame) --b;
    return frames.subspan(a, b - a);
}

std::string frame_hex(Frame f) {
    static constexpr char digits[] = "0123456789ABCDEF";
    return {'0', 'x', digits[f >> 4], digits[f & 0xF]};
}

}  // namespace tape
