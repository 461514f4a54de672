#include "sw/output/digest.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <memory>
#include <stdexcept>

#include <openssl/evp.h>

namespace cdvp {

namespace {

struct ContextFree {
    void operator()(EVP_MD_CTX* context) const { EVP_MD_CTX_free(context); }
};

class Sha256 {
public:
    Sha256() : context_(EVP_MD_CTX_new()) {
        if (!context_ || EVP_DigestInit_ex(context_.get(), EVP_sha256(), nullptr) != 1) {
            throw std::runtime_error("OpenSSL: cannot start a SHA-256 digest");
        }
    }
    void add(const void* data, std::size_t size) { EVP_DigestUpdate(context_.get(), data, size); }
    std::string hex() {
        unsigned char digest[EVP_MAX_MD_SIZE];
        unsigned int size = 0;
        EVP_DigestFinal_ex(context_.get(), digest, &size);
        static const char kHex[] = "0123456789abcdef";
        std::string text;
        for (unsigned int k = 0; k < size; ++k) {
            text += kHex[digest[k] >> 4];
            text += kHex[digest[k] & 15];
        }
        return text;
    }

private:
    std::unique_ptr<EVP_MD_CTX, ContextFree> context_;
};

}  // namespace

std::string sha256_hex(const std::string& bytes) {
    Sha256 digest;
    digest.add(bytes.data(), bytes.size());
    return digest.hex();
}

bool read_file_blocks(const std::string& path, const std::function<void(const char*, std::size_t)>& take) {
    const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    char block[1 << 16];
    for (;;) {
        const ssize_t got = read(fd, block, sizeof block);
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) {
            const int error = errno;
            close(fd);
            errno = error;
            return false;
        }
        if (got == 0) break;
        take(block, static_cast<std::size_t>(got));
    }
    close(fd);
    return true;
}

std::optional<FileDigest> digest_file(const std::string& path) {
    Sha256 digest;
    FileDigest result;
    const bool read = read_file_blocks(path, [&](const char* data, std::size_t size) {
        digest.add(data, size);
        result.bytes += size;
    });
    if (!read) return std::nullopt;
    result.sha256 = digest.hex();
    return result;
}

}  // namespace cdvp
