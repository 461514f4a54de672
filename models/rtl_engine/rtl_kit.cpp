#include "models/rtl_engine/rtl_kit.h"

#include <filesystem>

namespace cdvp {

std::vector<std::string> RtlKit::files() const {
    std::vector<std::string> all = verilog;
    all.insert(all.end(), cxx.begin(), cxx.end());
    return all;
}

const RtlKit& rtl_kit() {
    // The executable does not move while it runs: looked up once.
    static const RtlKit kit = [] {
        std::error_code ec;
        const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", ec);
        if (!ec) {
            const std::filesystem::path installed = executable.parent_path() / kRtlKitInstalledRelative;
            if (std::filesystem::is_directory(installed, ec)) return rtl_kit_at(installed.lexically_normal().string());
        }
        return rtl_kit_at(kRtlKitSourceRoot);
    }();
    return kit;
}

}  // namespace cdvp
