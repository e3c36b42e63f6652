#include <iostream>

#include "zrender/base/HeapPages.hpp"
#include "zrender/cli/CommandLine.hpp"
#include "zrender/io/files/InterruptCleanup.hpp"

int main(int argc, char** argv) {
  zrender::useHugePagesForHeap();
  zrender::removeInFlightFilesOnSignals();
  return zrender::runCommandLine(argc, argv, std::cout, std::cerr);
}
