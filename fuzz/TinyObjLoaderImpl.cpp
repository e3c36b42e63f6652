// tinyobjloader's implementation, compiled into the fuzz build with the fuzz instrumentation
// (TINYOBJLOADER_USE_DOUBLE comes from the target, as with tinyobjloader_double).
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
