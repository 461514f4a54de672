// An output file that appears at its final path only once complete: data go
// to a temporary file next to it, renamed into place by commit().
#pragma once

#include <fstream>
#include <memory>
#include <ostream>
#include <string>

namespace cdvp {

class OutputFile {
public:
    // Creates "<final_path>.part-XXXXXX<suffix>" in final_path's directory
    // (unique, via mkstemps) and, if open_stream, opens stream() on it. With
    // open_stream false the caller has some library write temp_path() itself;
    // 'suffix' is for libraries that append an extension to a base name (for
    // a VCD, pass ".vcd" and give the library temp_path() minus ".vcd").
    // Throws InputError "FINAL_PATH: cannot write: <reason>".
    explicit OutputFile(std::string final_path, std::string suffix = "",
                        bool open_stream = true);
    ~OutputFile();

    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;
    OutputFile(OutputFile&& other) noexcept;
    OutputFile& operator=(OutputFile&& other) noexcept;

    // The stream on the temporary file; std::logic_error without one.
    std::ostream& stream();
    const std::string& temp_path() const { return temp_path_; }
    const std::string& final_path() const { return final_path_; }

    // Flushes and closes the stream, checks for write errors and renames the
    // temporary file to the final path (replacing any file there). Throws
    // InputError "FINAL_PATH: cannot write: <reason>"; the temporary file is
    // then still removed by the destructor.
    void commit();

private:
    void discard() noexcept;
    [[noreturn]] void fail(int err) const;

    std::string final_path_;
    std::string temp_path_;  // empty once committed, discarded or moved from
    std::unique_ptr<std::ofstream> stream_;
};

}  // namespace cdvp
