#include "sw/output/created_directories.h"

#include <filesystem>
#include <system_error>

#include "models/common/input_path.h"
#include "models/common/user_text.h"

namespace cdvp {

void CreatedDirectories::create(const std::string& path, const std::string& label) {
    namespace fs = std::filesystem;
    std::error_code error;
    std::vector<fs::path> missing;
    for (fs::path p = fs::absolute(path); !p.empty() && !fs::exists(p, error); p = p.parent_path()) {
        missing.push_back(p);
        if (p == p.parent_path()) break;
    }
    if (missing.empty() && !fs::is_directory(path, error)) {
        throw InputError(label + ": " + path_text(path) + ": expected a directory");
    }
    for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
        if (fs::create_directory(*it, error)) {
            made_.push_back(it->string());
        } else if (error) {
            throw InputError(label + ": " + path_text(path) + ": cannot create: " + error.message());
        }  // else another process made it meanwhile: not this one's to remove
    }
}

CreatedDirectories::~CreatedDirectories() {
    std::error_code ignored;
    for (auto it = made_.rbegin(); it != made_.rend(); ++it) std::filesystem::remove(*it, ignored);
}

}  // namespace cdvp
