#include <iostream>

#include "zrender/base/HeapPages.hpp"
#include "zrender/cli/CommandLine.hpp"

int main(int argc, char** argv) {
  zrender::useHugePagesForHeap();
  return zrender::runCommandLine(argc, argv, std::cout, std::cerr);
}
