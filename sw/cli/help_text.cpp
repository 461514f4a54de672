#include "sw/cli/help_text.h"

#include <sstream>
#include <vector>

#include "sw/cli/exit_status.h"

namespace cdvp {

namespace {

std::size_t indent_of(const std::string& line) {
    const std::size_t indent = line.find_first_not_of(' ');
    return indent == std::string::npos ? 0 : indent;
}

// Where a row's second column starts ("  --frames F (...)   the frames ...",
// "  run       simulate ..."), if the line is a row of two columns.
std::size_t second_column(const std::string& line) {
    const std::size_t gap = line.find("  ", indent_of(line));
    if (gap == std::string::npos) return 0;
    const std::size_t column = line.find_first_not_of(' ', gap);
    return column == std::string::npos ? 0 : column;
}

// Where the continuation of a long line starts: under a row's second column,
// under a usage line's first argument, else under the line's own indent.
std::size_t continuation_column(const std::string& line) {
    if (line.rfind("Usage: ", 0) == 0) {
        const std::size_t argument = line.find_first_of("[(-", 7);
        return argument == std::string::npos ? 7 : argument;
    }
    if (const std::size_t column = second_column(line)) return column;
    const std::size_t indent = indent_of(line);
    return line.compare(indent, 1, "-") == 0 ? indent + 4 : indent;
}

void trim_right(std::string& line) {
    const std::size_t end = line.find_last_not_of(' ');
    line.erase(end == std::string::npos ? 0 : end + 1);
}

void wrap_line(std::string line, std::size_t column, std::size_t width, std::ostream& out) {
    while (line.size() > width) {
        // The last space within the width that leaves text on both sides;
        // else (a word longer than the width) the first space after it.
        std::size_t cut = line.rfind(' ', width);
        if (cut == std::string::npos || cut <= column) cut = line.find(' ', width);
        if (cut == std::string::npos) break;
        std::string head = line.substr(0, cut);
        trim_right(head);
        out << head << '\n';
        const std::size_t rest = line.find_first_not_of(' ', cut);
        if (rest == std::string::npos) return;
        line = std::string(column, ' ') + line.substr(rest);
    }
    out << line << '\n';
}

// A paragraph: lines of prose at one indent (no rows, no usage, no blank).
// (An indented line that starts with '-' is an option; at the margin it is
// prose that names one.)
bool is_prose(const std::string& line) {
    const std::size_t indent = indent_of(line);
    return !line.empty() && line.rfind("Usage: ", 0) != 0 && second_column(line) == 0 &&
           (indent == 0 || line.compare(indent, 1, "-") != 0);
}

}  // namespace

std::string wrapped_help(const std::string& text, std::size_t width) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        trim_right(line);
        lines.push_back(line);
    }
    std::ostringstream out;
    for (std::size_t k = 0; k < lines.size();) {
        // A paragraph of prose with a line too long is refilled as one;
        // other lines keep their breaks and wrap alone.
        // A row takes the indented prose under it as the rest of its second
        // column.
        std::size_t end = k + 1;
        bool too_long = lines[k].size() > width;
        const std::size_t column = second_column(lines[k]);
        const bool row = column > 0 && lines[k].rfind("Usage: ", 0) != 0;
        if (row || is_prose(lines[k])) {
            const std::size_t indent = indent_of(lines[k]);
            while (end < lines.size() && is_prose(lines[end]) &&
                   (row ? indent_of(lines[end]) > indent : indent_of(lines[end]) == indent)) {
                too_long |= lines[end].size() > width;
                ++end;
            }
        }
        if (end - k > 1 && too_long) {
            std::string paragraph = lines[k];
            for (std::size_t j = k + 1; j < end; ++j) paragraph += " " + lines[j].substr(indent_of(lines[j]));
            wrap_line(paragraph, row ? column : indent_of(lines[k]), width, out);
        } else {
            for (std::size_t j = k; j < end; ++j) wrap_line(lines[j], continuation_column(lines[j]), width, out);
        }
        k = end;
    }
    std::string result = out.str();
    if (!text.empty() && text.back() != '\n' && !result.empty()) result.pop_back();
    return result;
}

int print_help(const std::string& program, const std::string& text) {
    return print_to_stdout(program, wrapped_help(text));
}

}  // namespace cdvp
