#include "models/common/pinned_files.h"

#include <stdexcept>

namespace cdvp {

namespace {
const PinnedFiles* living_pins = nullptr;
}  // namespace

PinnedFiles::PinnedFiles() {
    if (living_pins != nullptr) throw std::logic_error("PinnedFiles: another set of pins is alive");
    living_pins = this;
}

PinnedFiles::~PinnedFiles() { living_pins = nullptr; }

void PinnedFiles::pin(const std::string& path, std::string text) { texts_[path] = std::move(text); }

const std::string* PinnedFiles::find(const std::string& path) {
    if (living_pins == nullptr) return nullptr;
    const auto at = living_pins->texts_.find(path);
    return at == living_pins->texts_.end() ? nullptr : &at->second;
}

}  // namespace cdvp
