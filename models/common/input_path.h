// Files a user names as inputs (a preset, a config file, a host profile, a
// trace): why one cannot be read, said the same way wherever it is opened,
// from the errno the system gave: its words and its name, so that a symbolic
// link loop, a directory or a file without read permission each says so
// ("p.json: cannot open: Too many levels of symbolic links (ELOOP)"), and
// only a name with nothing behind it is "no such file".
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

namespace cdvp {

// A file's path in a message: printable and whole, so that the file's name
// and the line and field after it are never cut away (a path the system
// opened is at most PATH_MAX, 4096 bytes). A longer one, which no file has,
// keeps its first and last kExcerptBytes around "... (N bytes) ...".
std::string path_text(const std::string& path);

// "Too many levels of symbolic links (ELOOP)"; for 0: "not a regular file".
std::string errno_reason(int error);

// What stat() says of a user-named input: present (anything is there,
// followed through links), absent (ENOENT: nothing by that name), or
// unreadable, with the reason (a loop, a component that is no directory, a
// directory without search permission, a name too long).
struct InputPresence {
    enum class Kind { kPresent, kAbsent, kUnreadable };
    Kind kind = Kind::kAbsent;
    std::string reason;  // kUnreadable: errno_reason
    bool present() const { return kind == Kind::kPresent; }
    bool absent() const { return kind == Kind::kAbsent; }
};
InputPresence input_presence(const std::string& path);

// Throws InputError "SHOWN: cannot open: REASON" (errno_reason(error)),
// then "; EXPECTED" when given: how every input that cannot be read is refused.
[[noreturn]] void refuse_input(const std::string& shown, int error, const std::string& expected = {});

// Throws InputError "PATH: cannot open: REASON" unless a regular file is
// there (a directory: "Is a directory (EISDIR)"); 'path' as the message
// shows it is given by 'shown' when not empty.
void require_regular_file(const std::string& path, const std::string& shown = {});

// One way to read an input file whole, for every file cdvp reads back (a
// preset, a config file, a host profile, a shared software timing, a model
// cache's stamp): opened without blocking (O_NONBLOCK, so a FIFO or a device
// never holds the open) and checked on that descriptor to be a regular file
// ("PATH: cannot open: not a regular file; expected WHAT": a link to
// /dev/zero, a FIFO, a directory), refused when larger than max_bytes before
// a byte is read ("PATH: larger than N bytes; not WHAT") or when it grows
// past them as it is read, and read to its end. Each block goes to `take`.
// Returns false, reading nothing, when there is no file and `absent_ok`;
// every other failure is an InputError naming the path (path_text).
struct InputFile {
    std::string path;
    std::string what;  // "a board preset", "a software timing cdvp wrote"
    std::size_t max_bytes = 0;
    bool absent_ok = false;
};
bool read_input_blocks(const InputFile& file, const std::function<void(const char*, std::size_t)>& take);
// The whole text; nothing only when there is no file and `absent_ok`.
std::optional<std::string> read_input_file(const InputFile& file);

}  // namespace cdvp
