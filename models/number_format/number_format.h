// The number format of the board's comparators and coordinate memories:
// float32 (the seed's) or unsigned fixed point of K bits (8 <= K <= 32).
#pragma once

#include <cstdint>
#include <cstring>
#include <string>

namespace cdvp {

// The six coordinates of a box in block RAM: the primitives' aspect and how
// many coordinates share one word of it.
struct BlockRamLayout {
    static constexpr uint32_t kCoordinates = 6;
    uint32_t width = 36;                // bits a word
    uint32_t depth = 512;               // words a primitive: boxes it holds
    uint32_t coordinates_per_word = 1;  // coordinates of one box side by side in a word

    // Primitives side by side to hold all six coordinates: ceil(6 / coordinates_per_word).
    uint32_t word_groups() const { return (kCoordinates + coordinates_per_word - 1) / coordinates_per_word; }
    // Primitives for one copy of the six coordinates of `boxes` boxes.
    uint64_t primitives(uint64_t boxes) const { return word_groups() * ((boxes + depth - 1) / depth); }
};

// A value type. What a comparison means lives here, so that both engines
// and the resource model ask the same object:
//   float32: IEEE comparisons (NaN never true, -0 == +0, denormals as they are);
//   fixedK:  unsigned comparisons of the word's low K bits (the memories are
//            K bits wide and keep only those bits of what the host writes).
// The fast engine compares ordered keys instead (key()): for every word that
// is not excluded(), key(a) <= key(b) exactly when a <= b in the format.
class NumberFormat {
public:
    static constexpr uint32_t kMinFixedBits = 8;
    static constexpr uint32_t kMaxFixedBits = 32;

    // float32.
    NumberFormat() = default;
    static NumberFormat float32() { return NumberFormat(); }
    // Throws std::invalid_argument unless 8 <= bits <= 32.
    static NumberFormat fixed(uint32_t bits);
    // "float32" or "fixed8" .. "fixed32"; throws std::invalid_argument with
    // one line "expected float32 or fixedK with K from 8 to 32, got 'TEXT'".
    static NumberFormat parse(const std::string& text);
    // The board's FORMAT register: 0 for float32, K for fixedK. Throws
    // std::invalid_argument for any other value.
    static NumberFormat from_register(uint32_t value);
    uint32_t register_value() const { return fixed_bits_; }

    bool is_float() const { return fixed_bits_ == 0; }
    // "float32", "fixed16".
    std::string name() const;
    // Width of a coordinate word: 32 for float32, K for fixedK.
    uint32_t bits() const { return is_float() ? 32 : fixed_bits_; }
    // The bits of a host's word that the memories keep.
    uint32_t word_mask() const { return bits() == 32 ? 0xFFFF'FFFFu : (1u << bits()) - 1; }
    // Largest fixed-point value (the word mask), as the quantiser's scale.
    uint32_t max_code() const { return word_mask(); }

    // How the six coordinates of `boxes` boxes sit in 18-Kbit block RAM
    // primitives (Virtex-II and UltraScale RAMB18: 512x36, 1Kx18, 2Kx9): the
    // layout with the fewest primitives. Narrow words share the block RAM in
    // two ways: a narrower aspect is deeper (fixed16 in 1K x 18), and several
    // coordinates of one box fit side by side in a wider word (fixed16: min
    // and max of an axis in one 36-bit word, three primitives a copy instead
    // of six). A port reads all of a box's coordinates at one address either way.
    BlockRamLayout block_ram_layout(uint64_t boxes) const;

    // The comparator's a <= b on two stored words.
    bool less_equal(uint32_t a, uint32_t b) const;
    // Words that compare false with everything (float32 NaN): such a box meets nothing.
    bool excluded(uint32_t word) const { return is_float() && (word & 0x7FFF'FFFFu) > 0x7F80'0000u; }
    // An unsigned key in the format's order (for words not excluded): float32
    // bit patterns mapped monotonically with -0 made +0; fixedK the word's low K bits.
    uint32_t key(uint32_t word) const {
        if (!is_float()) return word & word_mask();
        const uint32_t w = word == 0x8000'0000u ? 0u : word;  // -0 equals +0
        // Negative floats: all bits flipped; others: the sign bit set.
        return w ^ (static_cast<uint32_t>(static_cast<int32_t>(w) >> 31) | 0x8000'0000u);
    }
    // A value that grows with the key (float32: the float itself; fixedK: the
    // code): for cell choice in value space, monotone, so pruning stays exact.
    float approximate(uint32_t key) const { return is_float() ? float32_value(key) : fixed_value(key); }
    // The two cases, for loops that choose once.
    static float fixed_value(uint32_t key) { return static_cast<float>(key); }
    static float float32_value(uint32_t key) {
        const uint32_t flipped = key ^ 0x8000'0000u;  // key() undone
        const uint32_t word = flipped ^ (static_cast<uint32_t>(static_cast<int32_t>(flipped) >> 31) & 0x7FFF'FFFFu);
        float value;
        std::memcpy(&value, &word, sizeof value);
        return value;
    }

    friend bool operator==(NumberFormat a, NumberFormat b) { return a.fixed_bits_ == b.fixed_bits_; }
    friend bool operator!=(NumberFormat a, NumberFormat b) { return !(a == b); }

private:
    explicit NumberFormat(uint32_t fixed_bits) : fixed_bits_(fixed_bits) {}
    uint32_t fixed_bits_ = 0;  // 0: float32
};

}  // namespace cdvp
