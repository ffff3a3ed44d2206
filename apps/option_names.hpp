#pragma once
// The command-line spelling of the smoother's enums, used both to parse
// option values and to print them back (reports, --help), so the two never
// drift apart.
#include <string>

#include "apps/progress_line.hpp"
#include "kernels/smooth_options.hpp"
#include "mesh/io/mesh_io.hpp"

namespace tetsmooth::cli {

// Each throws UsageError naming `option` and listing the accepted values.
Method parse_method(const std::string& option, const std::string& text);
Form parse_form(const std::string& option, const std::string& text);
Strategy parse_strategy(const std::string& option, const std::string& text);
Layout parse_layout(const std::string& option, const std::string& text);
Device parse_device(const std::string& option, const std::string& text);
Precision parse_precision(const std::string& option, const std::string& text);
ProgressMode parse_progress_mode(const std::string& option, const std::string& text);

const char* option_name(Method m);
const char* option_name(Form f);
const char* option_name(Strategy s);
const char* option_name(Layout l);
const char* option_name(Device d);
const char* option_name(Precision p);
const char* option_name(Ordering o);

// The format of an input file as reports name it: "msh" for every Gmsh
// variant, because the reader detects the version and encoding itself and
// the name alone cannot tell them apart.
const char* input_format_name(MeshFormat f);

}  // namespace tetsmooth::cli
