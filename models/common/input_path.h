// Files a user names as inputs (a preset, a config file, a host profile, a
// trace): why one cannot be read, said the same way wherever it is opened,
// from the errno the system gave: its words and its name, so that a symbolic
// link loop, a directory or a file without read permission each says so
// ("p.json: cannot open: Too many levels of symbolic links (ELOOP)"), and
// only a name with nothing behind it is "no such file".
#pragma once

#include <string>

namespace cdvp {

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

}  // namespace cdvp
