#pragma once

#include <ostream>

namespace zrender {

// zrender's main: parses argv, runs the command, prints errors as docs/design.md, Errors says.
// Returns the exit status (0, 1 internal failure, 2 bad input or disagreement in bench).
int runCommandLine(int argc, char** argv, std::ostream& out, std::ostream& err);

}  // namespace zrender
