// Each box bank's words as the last upload into it left them, for delta
// uploads: a delta sends only the boxes whose words differ from the host
// bank's copy. The driver keeps them as it uploads (PortExecutor) and the
// analytic level as it plans its frames (AnalyticPlatform); unknown until a
// frame goes through, and after a fault.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "models/comparison_unit/comparison_unit.h"

namespace cdvp {

class BankCopies {
public:
    // Calls changed(i) for each box i < objects whose words (columns[c][i],
    // one column a coordinate) differ from the host bank's copy, every box
    // when it holds none; returns how many.
    template <class Changed>
    uint64_t compare(const uint32_t* const* columns, uint32_t objects, Changed changed) const {
        const Copy& bank = banks_[host_];
        const uint32_t known = bank.valid ? std::min(objects, bank.objects) : 0;
        uint64_t count = 0;
        for (uint32_t i = 0; i < objects; ++i) {
            bool same = i < known;
            for (uint32_t c = 0; same && c < kCoordinates; ++c) same = columns[c][i] == bank.words[c][i];
            if (!same) {
                changed(i);
                ++count;
            }
        }
        return count;
    }
    // The host bank holds these words now: copied, or swapped in (columns
    // takes the bank's old vectors).
    void keep(const uint32_t* const* columns, uint32_t objects) {
        Copy& bank = banks_[host_];
        for (uint32_t c = 0; c < kCoordinates; ++c) bank.words[c].assign(columns[c], columns[c] + objects);
        bank.objects = objects;
        bank.valid = true;
    }
    void take(std::vector<uint32_t>* columns, uint32_t objects) {
        Copy& bank = banks_[host_];
        for (uint32_t c = 0; c < kCoordinates; ++c) bank.words[c].swap(columns[c]);
        bank.objects = objects;
        bank.valid = true;
    }
    // What the board's memories hold is not known (a fault).
    void forget() {
        for (Copy& bank : banks_) bank.valid = false;
    }
    void set_host_bank(uint32_t bank) { host_ = bank; }
    // START hands the host's bank to the board: the other one is the host's.
    void hand_over() { host_ = 1 - host_; }

private:
    struct Copy {
        std::array<std::vector<uint32_t>, kCoordinates> words;
        uint32_t objects = 0;
        bool valid = false;
    };
    std::array<Copy, 2> banks_;
    uint32_t host_ = 0;  // the bank the next upload goes to
};

}  // namespace cdvp
