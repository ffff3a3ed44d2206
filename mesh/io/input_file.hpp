#pragma once
// Opening a mesh file for reading, with an InputError that names the path
// and the reason when it cannot be opened.
#include <fstream>
#include <string>

namespace tetsmooth {

std::ifstream open_input(const std::string& path);

}  // namespace tetsmooth
