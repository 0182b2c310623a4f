// Sixteen frames at once with GCC/Clang vector extensions: SSE2 on any x86-64, NEON on ARM,
// plain words elsewhere. Byte shifts are per lane, so the parity fold below is exact per byte.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__)) && \
    !defined(TAPE_NO_AVX2)  // -DTAPE_NO_AVX2 tests the rest
#include <cpuid.h>
#include <immintrin.h>
#define TAPE_SWAR_AVX2 1
#endif

namespace tape::swar {

#ifdef TAPE_SWAR_AVX2
/// The hot loops have an AVX2 twin (32 frames an instruction, nibble tables for parity), taken when the
/// CPU and the OS have it: the build stays plain x86-64, and the SSE2 loops below serve the rest. Asked
/// here, on first use, rather than through __builtin_cpu_supports, whose libgcc constructor would run
/// its CPUID probes (slow in a virtual machine) at the start of every command.
inline bool has_avx2() {
    static const bool yes = [] {
        unsigned a = 0, b = 0, c = 0, d = 0;
        if (!__get_cpuid(1, &a, &b, &c, &d) || !(c & bit_OSXSAVE) || !(c & bit_AVX)) return false;
        unsigned xcr0 = 0, high = 0;
        __asm__("xgetbv" : "=a"(xcr0), "=d"(high) : "c"(0));
        if ((xcr0 & 6) != 6) return false;  // the OS saves the XMM and YMM registers
        return __get_cpuid_count(7, 0, &a, &b, &c, &d) && (b & bit_AVX2);
    }();
    return yes;
}
#endif

/// Per nibble value 0..15: `odd` where it has an odd number of set bits, else 0; twice, for the two
/// 128-bit lanes of a vpshufb lookup.
template <std::uint8_t odd>
struct NibbleParity {
    alignas(32) std::uint8_t table[32];
    constexpr NibbleParity() : table{} {
        for (int i = 0; i < 32; ++i) table[i] = (__builtin_popcount(i & 15) & 1) ? odd : 0;
    }
};
template <std::uint8_t odd>
inline constexpr NibbleParity<odd> nibble_parity{};

/// Sixteen frames in a vector register.
typedef std::uint8_t bytes16 __attribute__((vector_size(16)));

inline bytes16 load16(const void* p) {
    bytes16 v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

inline void store16(void* p, bytes16 v) { std::memcpy(p, &v, sizeof v); }

/// The same sixteen bytes as two 64-bit lanes: whole-lane shifts need no per-byte masking.
typedef std::uint64_t words2 __attribute__((vector_size(16)));

/// Per byte: 1 where the byte has an odd number of set bits, else 0. The folds shift whole 64-bit
/// lanes; bits pulled in from the next byte land only above bit 3, 1 and 0 in turn, so bit 0 of each
/// byte stays exact.
inline bytes16 odd_parity16(bytes16 v) {
    words2 x = reinterpret_cast<words2>(v);
    x ^= x >> 4;
    x ^= x >> 2;
    x ^= x >> 1;
    return reinterpret_cast<bytes16>(x & 0x0101010101010101ULL);
}

/// Per byte: 0x80 where the byte has an odd number of set bits, else 0 (the ISO track 8 of a 7-bit code).
inline bytes16 parity_track16(bytes16 v) {
    words2 p = reinterpret_cast<words2>(odd_parity16(v));
    return reinterpret_cast<bytes16>(p << 7);
}

/// The sixteen bytes of v added up (each a count of at most 255): folded to 16-bit sums, then one multiply.
inline std::uint64_t byte_sum(bytes16 v) {
    words2 w = reinterpret_cast<words2>(v);
    w = (w & 0x00FF00FF00FF00FFULL) + ((w >> 8) & 0x00FF00FF00FF00FFULL);  // four 16-bit sums a lane
    return ((w[0] + w[1]) * 0x0001000100010001ULL) >> 48;
}

/// True when any byte of v is non-zero.
inline bool any16(bytes16 v) {
    std::uint64_t w[2];
    std::memcpy(w, &v, sizeof w);
    return (w[0] | w[1]) != 0;
}

/// What a line of program text holds, found in one pass: a byte of a multi-byte character (columns
/// must then count characters), a ';' (a Fanuc end of block or a comment), a ')' (a comment's end).
struct LineMarks {
    bool high = false, semicolon = false, close = false;
};

inline LineMarks line_marks(const char* p, std::size_t n) {
    bytes16 high{}, semicolon{}, close{};
    std::size_t i = 0;
    for (; i + 16 <= n; i += 16) {
        bytes16 v = load16(p + i);
        high |= v & 0x80;
        semicolon |= reinterpret_cast<bytes16>(v == ';');
        close |= reinterpret_cast<bytes16>(v == ')');
    }
    LineMarks m{.high = any16(high), .semicolon = any16(semicolon), .close = any16(close)};
    for (; i < n; ++i) {
        m.high |= (static_cast<unsigned char>(p[i]) & 0x80) != 0;
        m.semicolon |= p[i] == ';';
        m.close |= p[i] == ')';
    }
    return m;
}

/// One pass over text for the encoder: how many LF it holds, and whether any byte is NUL, CR or DEL
/// (which need a closer look).
struct TextScan {
    std::size_t newlines = 0;
    bool special = false;
};

inline TextScan scan_text(const char* p, std::size_t n) {
    TextScan s;
    bytes16 special{};
    std::size_t i = 0;
    for (; i + 16 <= n; i += 16) {
        bytes16 v = load16(p + i);
        auto ones = reinterpret_cast<words2>(reinterpret_cast<bytes16>(v == '\n') & 1);
        // The bytes of each lane are 0 or 1: the multiplication adds them up in the top byte.
        s.newlines += static_cast<std::size_t>((ones[0] * 0x0101010101010101ULL) >> 56) +
                      static_cast<std::size_t>((ones[1] * 0x0101010101010101ULL) >> 56);
        special |= reinterpret_cast<bytes16>((v == 0) | (v == '\r') | (v == 0x7F));
    }
    s.special = any16(special);
    for (; i < n; ++i) {
        char c = p[i];
        s.newlines += c == '\n';
        s.special |= c == '\0' || c == '\r' || c == '\x7F';
    }
    return s;
}

/// How many LF are among the n bytes at p: the line count of decoded text, one compare and one add
/// per sixteen bytes.
inline std::size_t count_newlines(const char* p, std::size_t n) {
    std::size_t count = 0, i = 0;
    while (i + 16 <= n) {
        bytes16 hits{};  // per byte lane: LFs seen, at most 255 before they are added up
        std::size_t end = n - i >= 255 * 16 ? i + 255 * 16 : n - (n - i) % 16;
        for (; i < end; i += 16) hits -= reinterpret_cast<bytes16>(load16(p + i) == '\n');
        count += static_cast<std::size_t>(byte_sum(hits));
    }
    for (; i < n; ++i) count += p[i] == '\n';
    return count;
}

}  // namespace tape::swar
