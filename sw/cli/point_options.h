// The options of a sweep's points, parsed as cdvp run parses them but
// cheaply: a point that differs from the last one parsed only in the values
// of setting flags ("--m=8") and of -c NAME=VALUE, each in the same place,
// takes that parse with its own values put in, each parsed by its setting as
// the flag or the setting layer would; any other difference, or a value its
// setting refuses, is parsed in full (so a refusal's words are the parser's).
#pragma once

#include <string>
#include <vector>

#include <boost/program_options.hpp>

#include "sw/cli/run_options.h"

namespace cdvp {

class PointOptions {
public:
    // As parse_run_options(argc, argv, options).
    boost::program_options::variables_map parse(int argc, char** argv, RunOptions& options);

    std::size_t reused() const { return reused_; }

private:
    // `options` and `vm` from the last parse with args' values in place of
    // its own; false when args differ in anything else.
    bool reuse(const std::vector<std::string>& args, RunOptions& options) const;

    std::vector<std::string> args_;
    RunOptions options_;
    boost::program_options::variables_map vm_;
    bool parsed_ = false;
    std::size_t reused_ = 0;
};

}  // namespace cdvp
