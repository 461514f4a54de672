// Directories an output needs, made as mkdir -p and removed again unless
// kept: a command that fails leaves none of the directories it made (they
// are empty then: its outputs' temporaries have gone first).
#pragma once

#include <string>
#include <vector>

namespace cdvp {

class CreatedDirectories {
public:
    // Makes PATH and its missing parents. 'label' names the path in messages
    // ("--out"); throws InputError when PATH names something other than a
    // directory or cannot be made.
    void create(const std::string& path, const std::string& label = "--out");
    bool made_any() const { return !made_.empty(); }
    void keep() { made_.clear(); }
    ~CreatedDirectories();

private:
    std::vector<std::string> made_;
};

}  // namespace cdvp
