#include <iostream>

#include "zrender/cli/CommandLine.hpp"

int main(int argc, char** argv) {
  return zrender::runCommandLine(argc, argv, std::cout, std::cerr);
}
