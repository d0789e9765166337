// tinyobjloader's implementation, compiled into PathLab where its library is not used
// (cmake/dependencies.cmake).
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
