#pragma once
// Opening a mesh file for reading, with an InputError that names the path
// and the reason when it cannot be opened.
#include <fstream>
#include <istream>
#include <string>

namespace tetsmooth {

std::ifstream open_input(const std::string& path);

// The rest of the stream as one string (for formats parsed in memory);
// InputError naming `source` on a read error.
std::string read_all(std::istream& in, const std::string& source);

}  // namespace tetsmooth
