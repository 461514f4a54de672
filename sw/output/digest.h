// SHA-256 digests, in the hex form `sha256sum` prints: what a sweep records of
// its inputs and of each point's report, so that a resume or a merge can tell
// a file it wrote from one changed since.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace cdvp {

std::string sha256_hex(const std::string& bytes);

// Reads the file at 'path' in blocks, giving each to 'take'; false when it
// cannot be opened or read (errno tells why).
bool read_file_blocks(const std::string& path, const std::function<void(const char*, std::size_t)>& take);

// A file's digest and size, read in blocks; nothing when it cannot be opened
// or read (errno tells why).
struct FileDigest {
    std::string sha256;
    uint64_t bytes = 0;
};
std::optional<FileDigest> digest_file(const std::string& path);

}  // namespace cdvp
