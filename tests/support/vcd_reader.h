// A small reader of the VCDs the platform writes, for tests: each signal's
// full name as a viewer resolves it (scopes joined by '.', a vector with its
// bit range) and every value change in time order.
#pragma once

#include <cstdint>
#include <istream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace cdvp::test {

struct VcdChange {
    uint64_t time;
    std::string id;
    std::string value;  // "0", "1", or a vector's binary digits
};

struct Vcd {
    std::map<std::string, std::string> id_of;  // full name -> identifier code
    std::vector<VcdChange> changes;            // the initial values at time 0 first

    // The value of 'name' at time t (the last change at or before it).
    std::string value_at(const std::string& name, uint64_t t) const {
        const std::string& id = id_of.at(name);
        std::string value;
        for (const VcdChange& c : changes) {
            if (c.time > t) break;
            if (c.id == id) value = c.value;
        }
        return value;
    }
};

inline Vcd read_vcd(std::istream& in) {
    Vcd vcd;
    std::vector<std::string> scopes;
    std::string word;
    uint64_t now = 0;
    while (in >> word) {
        if (word == "$scope") {
            std::string kind, name;
            in >> kind >> name;
            scopes.push_back(name);
        } else if (word == "$upscope") {
            scopes.pop_back();
        } else if (word == "$var") {
            // $var wire WIDTH ID NAME [RANGE] $end
            std::string kind, width, id, name, range;
            in >> kind >> width >> id >> name >> range;
            std::string full;
            for (const std::string& s : scopes) full += s + ".";
            vcd.id_of[full + name + (range == "$end" ? "" : range)] = id;
        } else if (word == "$date" || word == "$version" || word == "$timescale" || word == "$comment") {
            while (in >> word && word != "$end") {
            }
        } else if (word[0] == '#') {
            now = std::stoull(word.substr(1));
        } else if (word[0] == 'b') {
            std::string id;
            in >> id;
            vcd.changes.push_back({now, id, word.substr(1)});
        } else if (word[0] == '0' || word[0] == '1' || word[0] == 'x' || word[0] == 'z') {
            vcd.changes.push_back({now, word.substr(1), word.substr(0, 1)});
        }
    }
    return vcd;
}

inline Vcd read_vcd_text(const std::string& text) {
    std::istringstream in(text);
    return read_vcd(in);
}

}  // namespace cdvp::test
