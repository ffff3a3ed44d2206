// The command-line tool in-process: parsing and validation of arguments,
// exit codes, and the content of the reports.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numeric>
#include <sstream>

#include "apps/arg_parser.hpp"
#include "apps/cli.hpp"
#include "apps/command_line.hpp"
#include "apps/exit_codes.hpp"
#include "apps/input_warnings.hpp"
#include "apps/on_input_mesh.hpp"
#include "apps/output_check.hpp"
#include "apps/progress_line.hpp"
#include "apps/smoothing_pins.hpp"
#include "apps/report_text.hpp"
#include "apps/worst_tets.hpp"
#include "kernels/smoother.hpp"
#include "mesh/errors.hpp"
#include "mesh/io/mesh_io.hpp"
#include "mesh/io/writable_check.hpp"
#include "mesh/topology.hpp"
#include "scratch_dir.hpp"
#include "test_meshes.hpp"

namespace tetsmooth::cli {
namespace {

namespace fs = std::filesystem;

std::string contents_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

Command parse(std::vector<std::string> args) { return parse_command_line(args); }

template <class T>
T parse_as(std::vector<std::string> args) {
  const Command c = parse(std::move(args));
  EXPECT_TRUE(std::holds_alternative<T>(c));
  return std::get<T>(c);
}

std::string usage_error_of(std::vector<std::string> args) {
  try {
    parse(std::move(args));
  } catch (const UsageError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no UsageError";
  return "";
}

struct CliRun {
  int code;
  std::string out, err;
};

CliRun run(std::vector<std::string> args) {
  std::ostringstream out, err;
  const int code = run_cli(args, out, err, false);
  return {code, out.str(), err.str()};
}

// A fresh directory per test, removed afterwards.
class CliFiles : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
  // A jittered lattice-n mesh written by `tetsmooth generate`.
  std::string lattice(int n, const std::string& name = "lattice.vtu") {
    const std::string p = path(name);
    const CliRun r = run({"generate", "lattice-" + std::to_string(n), "-o", p, "-q"});
    EXPECT_EQ(r.code, kExitOk) << r.err;
    return p;
  }

  tetsmooth::testing::ScratchDir scratch_{"cli"};
  const fs::path dir_ = scratch_.path();
};

// --- parsing ---------------------------------------------------------------

TEST(CliParse, SmoothDefaultsAreThoseDocumented) {
  const auto c = parse_as<SmoothCommand>({"smooth", "in.vtu", "-o", "out.vtu"});
  EXPECT_EQ(c.input, "in.vtu");
  EXPECT_EQ(c.output, "out.vtu");
  EXPECT_EQ(c.options.method, Method::Adaptive);
  EXPECT_EQ(c.options.form, Form::B);
  EXPECT_EQ(c.options.strategy, Strategy::Coloured);
  EXPECT_EQ(c.options.layout, Layout::AoS);
  EXPECT_EQ(c.device, Device::Auto);
  EXPECT_EQ(c.options.threads, 0);
  EXPECT_EQ(c.options.precision, Precision::Double);
  EXPECT_EQ(c.options.max_iterations, 100);
  EXPECT_DOUBLE_EQ(c.options.tolerance, 1e-4);
  EXPECT_EQ(c.options.ordering, Ordering::Coloured);
  EXPECT_EQ(c.input_format, MeshFormat::Auto);
  EXPECT_EQ(c.output_format, MeshFormat::Auto);
  EXPECT_TRUE(c.report_path.empty());
  EXPECT_FALSE(c.quiet);
  EXPECT_EQ(c.progress, ProgressMode::Auto);
  EXPECT_FALSE(c.strategy_given || c.layout_given);
}

TEST(CliParse, SmoothTakesEveryOptionInBothSpellings) {
  const auto c = parse_as<SmoothCommand>({"smooth",
                                          "--method=ordinary",
                                          "--form",
                                          "A",
                                          "--strategy=multiblock",
                                          "--layout",
                                          "soa",
                                          "--device=cpu",
                                          "--threads",
                                          "3",
                                          "--precision",
                                          "float",
                                          "--max-iter=7",
                                          "--tol",
                                          "0.5",
                                          "--report",
                                          "r.json",
                                          "--format",
                                          "msh",
                                          "--output-format=vtk",
                                          "--progress=always",
                                          "-q",
                                          "in.msh",
                                          "--output",
                                          "out.txt"});
  EXPECT_EQ(c.input, "in.msh");
  EXPECT_EQ(c.output, "out.txt");
  EXPECT_EQ(c.options.method, Method::Ordinary);
  EXPECT_EQ(c.options.form, Form::A);
  EXPECT_EQ(c.options.strategy, Strategy::MultiBlock);
  EXPECT_EQ(c.options.layout, Layout::SoA);
  EXPECT_EQ(c.device, Device::Cpu);
  EXPECT_EQ(c.options.threads, 3);
  EXPECT_EQ(c.options.precision, Precision::Float);
  EXPECT_EQ(c.options.max_iterations, 7);
  EXPECT_DOUBLE_EQ(c.options.tolerance, 0.5);
  EXPECT_EQ(c.report_path, "r.json");
  EXPECT_EQ(c.input_format, MeshFormat::Msh41);
  EXPECT_EQ(c.output_format, MeshFormat::Vtk);
  EXPECT_EQ(c.progress, ProgressMode::Always);
  EXPECT_TRUE(c.quiet);
  EXPECT_TRUE(c.strategy_given && c.layout_given);
  // Form A is Jacobi: there is no node order to choose.
  EXPECT_EQ(c.options.ordering, Ordering::Natural);
}

TEST(CliParse, OnlyOneThreadGivesTheNaturalOrderOfTheSerialReference) {
  EXPECT_EQ(parse_as<SmoothCommand>({"smooth", "a.vtu", "-o", "b.vtu", "--threads", "1"}).options.ordering,
            Ordering::Natural);
  EXPECT_EQ(parse_as<SmoothCommand>({"smooth", "a.vtu", "-o", "b.vtu", "--threads", "2"}).options.ordering,
            Ordering::Coloured);
  EXPECT_EQ(parse_as<SmoothCommand>({"smooth", "a.vtu", "-o", "b.vtu", "--threads", "0"}).options.ordering,
            Ordering::Coloured);
}

TEST(CliParse, OtherCommands) {
  const auto g = parse_as<GenerateCommand>({"generate", "lattice-4", "-o", "x.vtu", "--seed", "18446744073709551615"});
  EXPECT_EQ(g.model, "lattice-4");
  EXPECT_EQ(g.seed, 18446744073709551615ull);
  EXPECT_EQ(parse_as<GenerateCommand>({"generate", "5k", "-o", "x.vtu"}).seed, 1u);

  const auto q = parse_as<QualityCommand>({"quality", "m.mesh", "--json", "--worst", "3"});
  EXPECT_TRUE(q.json);
  EXPECT_EQ(q.worst, 3);
  EXPECT_EQ(parse_as<QualityCommand>({"quality", "m.mesh"}).worst, 10);

  const auto v = parse_as<ConvertCommand>({"convert", "a.node", "b.msh", "--output-format", "msh22"});
  EXPECT_EQ(v.input, "a.node");
  EXPECT_EQ(v.output, "b.msh");
  EXPECT_EQ(v.output_format, MeshFormat::Msh22);
}

TEST(CliParse, DoubleDashEndsOptions) {
  const auto v = parse_as<ConvertCommand>({"convert", "--", "-odd.vtu", "b.vtu"});
  EXPECT_EQ(v.input, "-odd.vtu");
}

// A lone "-" is a file name by convention, not an option: it must reach the
// command as a positional rather than fail as "unknown option '-'".
TEST(CliParse, LoneDashIsAPositional) {
  const std::vector<OptionSpec> specs = {{"json", 0, false}};
  const ParsedArgs p = parse_args({"-", "--json"}, specs, "quality");
  EXPECT_EQ(p.positionals, std::vector<std::string>{"-"});
  EXPECT_EQ(p.values.count("json"), 1u);
}

TEST(CliParse, HelpAndVersion) {
  EXPECT_EQ(parse_as<HelpRequest>({"--help"}).command, "");
  EXPECT_EQ(parse_as<HelpRequest>({"-h"}).command, "");
  EXPECT_EQ(parse_as<HelpRequest>({"help", "quality"}).command, "quality");
  // Help wins over whatever else is on the line, even a bad option.
  EXPECT_EQ(parse_as<HelpRequest>({"smooth", "--bogus", "--help"}).command, "smooth");
  EXPECT_EQ(parse_as<HelpRequest>({"convert", "-h"}).command, "convert");
  parse_as<VersionRequest>({"--version"});
}

// After "--", "-h" and "--help" are file names like any other, not a request
// for help.
TEST(CliParse, HelpAfterDoubleDashIsAFileName) {
  const auto c = parse_as<ConvertCommand>({"convert", "--", "in.vtu", "--help"});
  EXPECT_EQ(c.input, "in.vtu");
  EXPECT_EQ(c.output, "--help");
  EXPECT_EQ(parse_as<QualityCommand>({"quality", "--", "-h"}).input, "-h");
}

// An empty --report (a shell variable left unset) is refused rather than
// taken as "no report".
TEST(CliParse, EmptyReportNameIsAUsageError) {
  EXPECT_EQ(usage_error_of({"smooth", "a.vtu", "-o", "b.vtu", "--report", ""}), "--report needs a file name");
}

// --worst 0 is the documented way to list no tets.
TEST(CliParse, WorstZeroListsNone) {
  EXPECT_EQ(parse_as<QualityCommand>({"quality", "a.vtu", "--worst", "0"}).worst, 0);
}

TEST(CliParse, UsageErrorsNameTheProblem) {
  EXPECT_NE(usage_error_of({}).find("no command"), std::string::npos);
  EXPECT_NE(usage_error_of({"smoothe", "a"}).find("unknown command 'smoothe'"), std::string::npos);
  EXPECT_NE(usage_error_of({"--frobnicate"}).find("unknown option '--frobnicate'"), std::string::npos);
  EXPECT_NE(usage_error_of({"help", "nope"}).find("no help for 'nope'"), std::string::npos);

  const std::string typo = usage_error_of({"smooth", "a.vtu", "-o", "b.vtu", "--max-iters", "5"});
  EXPECT_NE(typo.find("unknown option '--max-iters'"), std::string::npos) << typo;
  EXPECT_NE(typo.find("did you mean '--max-iter'"), std::string::npos) << typo;
  EXPECT_NE(typo.find("tetsmooth smooth --help"), std::string::npos) << typo;

  EXPECT_NE(usage_error_of({"smooth", "a.vtu"}).find("missing -o OUT"), std::string::npos);
  EXPECT_NE(usage_error_of({"smooth", "-o", "b.vtu"}).find("missing input"), std::string::npos);
  EXPECT_NE(usage_error_of({"smooth", "a.vtu", "x.vtu", "-o", "b.vtu"}).find("unexpected argument 'x.vtu'"),
            std::string::npos);
  EXPECT_NE(usage_error_of({"smooth", "a.vtu", "-o"}).find("-o needs a value"), std::string::npos);
  EXPECT_NE(usage_error_of({"convert", "a.vtu"}).find("missing OUT"), std::string::npos);
  EXPECT_NE(usage_error_of({"quality", "a.vtu", "--json=yes"}).find("takes no value"), std::string::npos);
  EXPECT_NE(usage_error_of({"smooth", "a.vtu", "-o", "b.vtu", "--form", "C"}).find("expected A|B"), std::string::npos);
  EXPECT_NE(usage_error_of({"smooth", "a.vtu", "-o", "b.vtu", "--device", "gpu"}).find("expected auto|cpu|cuda"),
            std::string::npos);
}

// A second value would silently replace the first.
TEST(CliParse, AnOptionWithAValueIsGivenOnce) {
  EXPECT_NE(usage_error_of({"smooth", "in.vtu", "-o", "a.vtu", "-o", "b.vtu"}).find("-o is given more than once"),
            std::string::npos);
  EXPECT_NE(usage_error_of({"smooth", "in.vtu", "-o", "a.vtu", "--output", "b.vtu"}).find("more than once"),
            std::string::npos);
  EXPECT_NE(usage_error_of({"smooth", "in.vtu", "-o", "a.vtu", "--tol=1e-3", "--tol", "1e-4"}).find("--tol"),
            std::string::npos);
}

// Both ends of a range are allowed values; one past either end is not.
TEST(CliParse, RangeEndsAreInclusive) {
  EXPECT_EQ(parse_int_option("--n", "0", 0, 100), 0);
  EXPECT_EQ(parse_int_option("--n", "100", 0, 100), 100);
  EXPECT_THROW(parse_int_option("--n", "-1", 0, 100), UsageError);
  EXPECT_THROW(parse_int_option("--n", "101", 0, 100), UsageError);
}

// A suggestion is offered for near misses only (at most two edits away):
// a far-fetched "did you mean" misleads more than it helps.
TEST(CliParse, SuggestionsAreForNearMissesOnly) {
  const std::vector<OptionSpec> specs = {{"threads", 0, true}};
  const auto message = [&](const std::string& token) {
    try {
      parse_args({token, "1"}, specs, "smooth");
    } catch (const UsageError& e) {
      return std::string(e.what());
    }
    return std::string("no UsageError");
  };
  EXPECT_NE(message("--thraeds").find("did you mean '--threads'"), std::string::npos);
  const std::string far = message("--thrxxxs");  // three substitutions away
  EXPECT_NE(far.find("unknown option '--thrxxxs'"), std::string::npos) << far;
  EXPECT_EQ(far.find("did you mean"), std::string::npos) << far;
}

// Trailing characters make a number invalid rather than being dropped:
// "--seed 12abc" must not run with seed 12.
TEST(CliParse, SeedsWithTrailingCharactersAreRejected) {
  EXPECT_EQ(parse_u64_option("--seed", "18446744073709551615"), 18446744073709551615u);
  for (const char* bad : {"12abc", "12 ", "1.5", "0x10"})
    EXPECT_THROW(parse_u64_option("--seed", bad), UsageError) << bad;
}

// Short options are single letters; "-qx" is not "-q" with a stray "x".
TEST(CliParse, ShortOptionsDoNotTakeGluedLetters) {
  const std::string e = usage_error_of({"quality", "a.vtu", "-qx"});
  EXPECT_NE(e.find("unknown option '-qx'"), std::string::npos) << e;
}

TEST(CliParse, NumbersAreCheckedForRange) {
  for (const char* bad : {"0", "-3", "ten", "5x", "", "99999999999"})
    EXPECT_THROW(parse({"smooth", "a.vtu", "-o", "b.vtu", "--max-iter", bad}), UsageError) << bad;
  for (const char* bad : {"-1", "nan", "inf", "1e-4x", "abc"})
    EXPECT_THROW(parse({"smooth", "a.vtu", "-o", "b.vtu", "--tol", bad}), UsageError) << bad;
  EXPECT_THROW(parse({"smooth", "a.vtu", "-o", "b.vtu", "--threads", "-1"}), UsageError);
  EXPECT_THROW(parse({"generate", "5k", "-o", "b.vtu", "--seed", "-1"}), UsageError);
  EXPECT_THROW(parse({"quality", "a.vtu", "--worst", "-1"}), UsageError);
  EXPECT_EQ(parse_int_option("--n", "42", 0, 100), 42);
  EXPECT_DOUBLE_EQ(parse_nonnegative_option("--x", "2.5e-3"), 2.5e-3);
}

TEST(CliParse, UnknownFormatNameIsAUsageError) {
  EXPECT_THROW(parse({"convert", "a.vtu", "b.vtu", "--output-format", "stl"}), UsageError);
}

TEST(CliParse, ProgressModesAndABadOne) {
  EXPECT_EQ(parse_as<SmoothCommand>({"smooth", "a.vtu", "-o", "b.vtu", "--progress", "never"}).progress,
            ProgressMode::Never);
  EXPECT_EQ(parse_as<SmoothCommand>({"smooth", "a.vtu", "-o", "b.vtu", "--progress=auto"}).progress,
            ProgressMode::Auto);
  try {
    parse({"smooth", "a.vtu", "-o", "b.vtu", "--progress", "sometimes"});
    ADD_FAILURE() << "--progress sometimes was accepted";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("--progress: expected auto|always|never"), std::string::npos) << e.what();
  }
}

// --- exit codes ------------------------------------------------------------

TEST(CliExit, UsageErrorsExitWith2AndOneLine) {
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {}, {"smooth", "--nope"}, {"quality"}, {"smooth", "a.vtu", "-o", "b.vtu", "--tol", "x"}}) {
    const CliRun r = run(args);
    EXPECT_EQ(r.code, kExitUsage);
    EXPECT_EQ(r.err.rfind("tetsmooth: error: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(r.out.empty());
  }
}

TEST(CliExit, HelpGoesToStdoutAndListsExitCodes) {
  for (const std::string command : {"", "generate", "smooth", "quality", "convert"}) {
    const CliRun r = command.empty() ? run({"--help"}) : run({command, "--help"});
    EXPECT_EQ(r.code, kExitOk);
    EXPECT_TRUE(r.err.empty());
    EXPECT_NE(r.out.find("Usage:"), std::string::npos) << command;
    EXPECT_NE(r.out.find("5  device error"), std::string::npos) << command;
  }
  EXPECT_NE(run({"smooth", "--help"}).out.find("--max-iter N"), std::string::npos);
  EXPECT_NE(run({"generate", "--help"}).out.find("slope-77k"), std::string::npos);
  const CliRun v = run({"--version"});
  EXPECT_EQ(v.code, kExitOk);
  EXPECT_EQ(v.out.rfind(std::string("tetsmooth ") + TETSMOOTH_VERSION, 0), 0u);
}

// Each help's exit-status table gives each code the number the CLI returns
// (apps/exit_codes.hpp), for scripts that branch on it.
TEST(CliExit, HelpNumbersEachExitStatusAsReturned) {
  const std::pair<int, const char*> codes[] = {{kExitOk, "success"},          {kExitInternal, "internal error"},
                                               {kExitUsage, "usage error"},   {kExitInput, "bad input"},
                                               {kExitOutput, "output error"}, {kExitDevice, "device error"}};
  for (const std::string command : {"", "generate", "smooth", "quality", "convert"}) {
    const std::string help = command.empty() ? run({"--help"}).out : run({command, "--help"}).out;
    for (const auto& [code, name] : codes)
      EXPECT_NE(help.find("\n  " + std::to_string(code) + "  " + name), std::string::npos) << command << ": " << name;
  }
}

// The defaults smooth --help states are those the parser sets.
TEST(CliExit, SmoothHelpStatesTheParsedDefaults) {
  const auto c = parse_as<SmoothCommand>({"smooth", "in.vtu", "-o", "out.vtu"});
  const std::string help = run({"smooth", "--help"}).out;
  EXPECT_NE(help.find("at most N sweeps (default " + std::to_string(c.options.max_iterations) + ")"),
            std::string::npos);
  EXPECT_NE(help.find("(default " + std::to_string(c.options.threads) + ")"), std::string::npos);
  EXPECT_NE(help.find("length in a sweep (default 1e-4)"), std::string::npos);
  EXPECT_DOUBLE_EQ(c.options.tolerance, 1e-4);
}

// Each command's --help is that command's own usage, not the overview.
TEST(CliExit, EachCommandsHelpIsItsOwn) {
  for (const std::string command : {"generate", "smooth", "quality", "convert"}) {
    EXPECT_EQ(run({command, "--help"}).out.rfind("Usage: tetsmooth " + command + " ", 0), 0u) << command;
    EXPECT_EQ(run({"help", command}).out.rfind("Usage: tetsmooth " + command + " ", 0), 0u) << command;
  }
}

TEST(CliExit, UnknownModelIsAUsageError) {
  EXPECT_EQ(run({"generate", "no-such-model", "-o", "/tmp/never-written.vtu"}).code, kExitUsage);
}

TEST(CliExit, UnknownExtensionIsAUsageError) {
  const CliRun r = run({"convert", "a.vtu", "b.xyz"});
  EXPECT_EQ(r.code, kExitUsage);
  // The message names the way out: the options that name a format.
  EXPECT_NE(r.err.find("cannot tell the mesh format of 'b.xyz'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--output-format"), std::string::npos) << r.err;
}

TEST_F(CliFiles, MissingInputExitsWith3) {
  const CliRun r = run({"quality", path("absent.vtu")});
  EXPECT_EQ(r.code, kExitInput);
  EXPECT_NE(r.err.find("absent.vtu"), std::string::npos) << r.err;
}

// The command line takes a TetGen base name as the library does.
// A TetGen input named by its base name is the files base.node and
// base.ele: writing base.node replaces the input, and is warned as such.
TEST_F(CliFiles, TetGenBaseNameWrittenOverIsWarnedAsTheInput) {
  write_mesh(testing::cube_with_centre(), path("box.node"));
  const CliRun r = run({"convert", path("box"), path("box.node")});
  EXPECT_EQ(r.code, kExitOk) << r.err;
  EXPECT_NE(r.err.find(path("box.node") + " is the input mesh"), std::string::npos) << r.err;
}

TEST_F(CliFiles, TetGenBaseNameAsInput) {
  write_mesh(testing::cube_with_centre(), path("box.node"));
  const CliRun r = run({"convert", path("box"), path("box.vtu")});
  EXPECT_EQ(r.code, kExitOk) << r.err;
  EXPECT_EQ(read_mesh(path("box.vtu")).tets, testing::cube_with_centre().tets);
  EXPECT_EQ(run({"convert", path("nothing"), path("x.vtu")}).code, kExitUsage);
}

// A name of up to NAME_MAX bytes is written, though its temporary's is longer.
TEST_F(CliFiles, LongestFileNameIsWritten) {
  const std::string name = std::string(251, 'x') + ".vtu";
  const CliRun r = run({"convert", lattice(2), path(name)});
  EXPECT_EQ(r.code, kExitOk) << r.err;
  EXPECT_TRUE(fs::is_regular_file(path(name)));
}

TEST_F(CliFiles, DirectoryAsInputIsNamedAsSuch) {
  fs::create_directory(path("dir.msh"));
  const CliRun r = run({"quality", path("dir.msh")});
  EXPECT_EQ(r.code, kExitInput);
  EXPECT_NE(r.err.find("dir.msh: is a directory"), std::string::npos) << r.err;
  fs::create_directory(path("dir.tsm"));
  EXPECT_NE(run({"convert", path("dir.tsm"), path("x.vtu")}).err.find("is a directory"), std::string::npos);
}

TEST_F(CliFiles, MalformedInputExitsWith3AndNamesTheLine) {
  const std::string p = path("broken.mesh");
  std::ofstream(p) << "MeshVersionFormatted 2\nDimension 3\nVertices\n2\n0 0 0 0\n1 1 nonsense 0\n";
  const CliRun r = run({"quality", p});
  EXPECT_EQ(r.code, kExitInput);
  EXPECT_NE(r.err.find("broken.mesh:"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST_F(CliFiles, UnwritableOutputExitsWith4AndWritesNothing) {
  const std::string in = lattice(2);
  const std::vector<std::string> before = files();
  const CliRun missing_dir = run({"convert", in, path("no/such/dir/out.vtu")});
  EXPECT_EQ(missing_dir.code, kExitOutput) << missing_dir.err;
  fs::create_directory(path("taken.vtu"));
  const CliRun is_dir = run({"smooth", in, "-o", path("taken.vtu")});
  EXPECT_EQ(is_dir.code, kExitOutput) << is_dir.err;
  const CliRun report = run({"smooth", in, "-o", path("ok.vtu"), "--report", path("no/dir/r.json")});
  EXPECT_EQ(report.code, kExitOutput) << report.err;
  // TetGen's second file is checked as well as the one named.
  fs::create_directory(path("pair.ele"));
  const CliRun pair = run({"smooth", in, "-o", path("pair.node"), "--device", "cpu"});
  EXPECT_EQ(pair.code, kExitOutput) << pair.err;
  EXPECT_NE(pair.err.find("pair.ele': it is a directory"), std::string::npos) << pair.err;
  EXPECT_EQ(pair.err.find("done:"), std::string::npos) << "checked only after smoothing:\n" << pair.err;
  // The report's location is checked before smoothing, so not even the mesh
  // was written.
  std::vector<std::string> expected = before;
  expected.push_back("pair.ele");
  expected.push_back("taken.vtu");
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(files(), expected);
}

// A report path that names a mesh of the run, under any spelling, is refused
// before anything is read or written.
TEST_F(CliFiles, ReportOverAMeshIsAUsageError) {
  const std::string in = lattice(2, "in.vtu");
  const std::string before = contents_of(in);
  const std::vector<std::vector<std::string>> runs{
      {"smooth", in, "-o", path("out.vtu"), "--report", path("out.vtu")},
      {"smooth", in, "-o", path("out.vtu"), "--report", path("in.vtu")},
      {"smooth", in, "-o", path("out.vtu"), "--report", dir_.string() + "/./sub/../in.vtu"},
      {"smooth", in, "-o", path("out.ele"), "--report", path("out.node")}};
  fs::create_directory(path("sub"));
  for (const auto& args : runs) {
    const CliRun r = run(args);
    EXPECT_EQ(r.code, kExitUsage) << args.back() << ": " << r.err;
    EXPECT_NE(r.err.find("--report"), std::string::npos) << r.err;
  }
  EXPECT_EQ(contents_of(in), before);
  EXPECT_EQ(files(), (std::vector<std::string>{"in.vtu", "sub"}));
}

// A 3-node line read from MSH has no place in Nastran output: the run says
// so before it smooths anything, and writes nothing.
TEST_F(CliFiles, OutputThatCannotHoldTheElementsFailsBeforeSmoothing) {
  TetMesh mesh = testing::cube_with_centre();
  mesh.extras.blocks.push_back(PassThroughBlock{"line3", 3, {0, 1, 2}, {}, {}, {}});
  write_mesh(mesh, path("line3.msh"));
  for (const char* out : {"out.bdf", "out.nas"}) {
    const CliRun r = run({"smooth", path("line3.msh"), "-o", path(out), "--device", "cpu"});
    EXPECT_EQ(r.code, kExitOutput) << r.err;
    EXPECT_NE(r.err.find("line3"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("done:"), std::string::npos) << "smoothed before failing:\n" << r.err;
  }
  EXPECT_EQ(run({"convert", path("line3.msh"), path("out.bdf")}).code, kExitOutput);
  EXPECT_EQ(files(), std::vector<std::string>{"line3.msh"});
  // Formats that hold it go through.
  EXPECT_EQ(run({"smooth", path("line3.msh"), "-o", path("out.vtu"), "--device", "cpu", "-q"}).code, kExitOk);
}

// Whether any of `notes` contains `text`.
bool has_note(const std::vector<std::string>& notes, const std::string& text) {
  for (const std::string& n : notes)
    if (n.find(text) != std::string::npos) return true;
  return false;
}

// Each loss is named for the formats that drop it and for no other, and
// only when there is something to lose.
TEST(OutputLosses, EachNoteGoesWithTheFormatsThatDropIt) {
  // TetGen and .tsm hold tets only; an empty block loses nothing and is not
  // listed among what is lost.
  TetMesh hex = testing::cube_with_centre();
  hex.extras.blocks.push_back(PassThroughBlock{"triangle", 3, {}, {}, {}, {}});
  hex.extras.blocks.push_back(PassThroughBlock{"hexahedron", 8, {0, 1, 2, 3, 4, 5, 6, 7}, {}, {}, {}});
  const auto tetgen = output_losses(hex, "out.node");
  ASSERT_FALSE(tetgen.empty());
  EXPECT_EQ(tetgen[0], "1 hexahedron will not be written: tetgen holds tets only");
  EXPECT_TRUE(has_note(output_losses(hex, "out.tsm"), "1 hexahedron will not be written: tsm holds tets only"));

  // Node markers: TetGen writes them, Medit as vertex references; VTU not.
  TetMesh marked = testing::regular_tet();
  marked.extras.node_markers = {1, 0, 0, 2};
  EXPECT_FALSE(has_note(output_losses(marked, "out.node"), "node markers"));
  EXPECT_FALSE(has_note(output_losses(marked, "out.mesh"), "node markers"));
  EXPECT_TRUE(has_note(output_losses(marked, "out.vtu"), "the node markers will not be written"));

  // A node attribute count without values has nothing to lose.
  TetMesh counted = testing::regular_tet();
  counted.extras.node_attribute_count = 2;
  EXPECT_FALSE(has_note(output_losses(counted, "out.vtu"), "node attributes"));

  // TetGen writes its tet attributes back; VTU keeps only the region tags.
  TetMesh attributes = testing::regular_tet();
  attributes.extras.tet_attribute_count = 2;
  attributes.extras.tet_attributes = {1, 0.5};
  EXPECT_FALSE(has_note(output_losses(attributes, "out.node"), "tet attributes"));
  EXPECT_TRUE(has_note(output_losses(attributes, "out.vtu"), "the TetGen tet attributes (2 per tet)"));

  // .tsm alone drops the region tags.
  TetMesh tagged = testing::regular_tet();
  tagged.extras.tet_tags = {3};
  EXPECT_TRUE(has_note(output_losses(tagged, "out.tsm"), "the region tags will not be written: tsm"));
  EXPECT_FALSE(has_note(output_losses(tagged, "out.vtu"), "region tags"));
}

// MSH keeps a pin through an element on the node (a vertex here), TetGen
// keeps none: of two pinned interior nodes, one on a vertex element, MSH
// loses one pin and TetGen both.
TEST(OutputLosses, PinsKeptByElementsOnlyWhereTheFormatWritesThem) {
  TetMesh mesh = testing::cube_grid(3);
  const index_t on_vertex = 1 + 4 * (1 + 4 * 1), bare = 2 + 4 * (2 + 4 * 2);  // interior nodes (1,1,1), (2,2,2)
  mesh.fixed.assign(mesh.num_nodes(), 0);
  mesh.fixed[static_cast<std::size_t>(on_vertex)] = 1;
  mesh.fixed[static_cast<std::size_t>(bare)] = 1;
  mesh.extras.blocks.push_back(PassThroughBlock{"vertex", 1, {on_vertex}, {}, {}, {}});
  EXPECT_TRUE(has_note(output_losses(mesh, "out.msh"),
                       "1 pinned node will not be pinned in the msh41 output, so a later run may move it"));
  EXPECT_TRUE(has_note(output_losses(mesh, "out.node"),
                       "2 pinned nodes will not be pinned in the tetgen output, so a later run may move them"));
}

// Medit has no point elements: a vertex block goes out as RequiredVertices,
// its pin kept, its elements and their tags (a Gmsh physical point, say)
// not; the run says so. Other formats keep the block.
TEST(OutputLosses, PointElementsLoseTheirTagsInMedit) {
  TetMesh mesh = testing::cube_grid(3);
  const index_t a = 1 + 4 * (1 + 4 * 1), b = 2 + 4 * (2 + 4 * 2);
  mesh.extras.blocks.push_back(PassThroughBlock{"vertex", 1, {a, b}, {40, 40}, {}, {}});
  EXPECT_TRUE(has_note(output_losses(mesh, "out.mesh"),
                       "2 point elements will be written as RequiredVertices, without their tags or element ids "
                       "(their nodes stay pinned): medit has no point elements"));
  for (const char* other : {"out.msh", "out.vtu", "out.vtk"})
    EXPECT_FALSE(has_note(output_losses(mesh, other), "point element")) << other;
  mesh.extras.blocks.back().connectivity.pop_back();
  mesh.extras.blocks.back().tags.pop_back();
  EXPECT_TRUE(has_note(output_losses(mesh, "out.mesh"),
                       "1 point element will be written as RequiredVertices, without its tag or element id (its node "
                       "stays pinned): medit has no point elements"));
}

// The probe's failure names the file the run would have written, as the
// writer's own "cannot write 'path': ..." does, not only the reason.
TEST(CheckWritable, NamesThePathAndTheReason) {
  TetMesh mesh = testing::cube_with_centre();
  mesh.extras.blocks.push_back(PassThroughBlock{"line3", 3, {0, 1, 2}, {}, {}, {}});
  EXPECT_NO_THROW(check_writable(mesh, "out.msh"));
  try {
    check_writable(mesh, "out.bdf");
    FAIL() << "no OutputError";
  } catch (const OutputError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind("cannot write 'out.bdf': ", 0), 0u) << msg;
    EXPECT_NE(msg.find("line3"), std::string::npos) << msg;
  }
}

// What the output format cannot carry is named before the work: elements
// other than tets to TetGen, pins to MSH, node attributes to VTU.
// The per-tet quality and per-node boundary fields are what a ParaView user
// thresholds on; every format that can hold fields must get them, whichever
// way its name is spelled on the command line.
TEST_F(CliFiles, EveryFormatWithFieldsCarriesQualityAndBoundary) {
  write_mesh(testing::cube_with_centre(), path("in.vtu"));
  for (const char* format : {"vtu", "vtk", "msh41", "msh41-binary", "msh22"}) {
    const std::string out = path(std::string("out_") + format);
    const CliRun r = run({"convert", path("in.vtu"), out, "--output-format", format});
    ASSERT_EQ(r.code, kExitOk) << format << ": " << r.err;
    const std::string text = contents_of(out);
    EXPECT_NE(text.find("quality"), std::string::npos) << format;
    EXPECT_NE(text.find("boundary"), std::string::npos) << format;
  }
}

TEST_F(CliFiles, WhatTheOutputFormatDropsIsNamed) {
  TetMesh mesh = testing::cube_with_centre();
  mesh.extras.blocks.push_back(PassThroughBlock{"hexahedron", 8, {0, 1, 2, 3, 4, 5, 6, 7}, {}, {}, {}});
  write_mesh(mesh, path("hex.msh"));
  const CliRun tetgen = run({"convert", path("hex.msh"), path("hex.node")});
  EXPECT_EQ(tetgen.code, kExitOk) << tetgen.err;
  EXPECT_NE(tetgen.err.find("1 hexahedron will not be written: tetgen holds tets only"), std::string::npos)
      << tetgen.err;

  TetMesh pinned = testing::cube_with_centre();
  pinned.extras.required_nodes = {8};
  pinned.fixed.assign(9, 0);
  pinned.fixed[8] = 1;
  write_mesh(pinned, path("pinned.mesh"));
  const CliRun msh = run({"smooth", path("pinned.mesh"), "-o", path("out.msh"), "--device", "cpu"});
  EXPECT_EQ(msh.code, kExitOk) << msh.err;
  EXPECT_NE(msh.err.find("1 pinned node will not be pinned in the msh41 output"), std::string::npos) << msh.err;
  const CliRun medit = run({"convert", path("pinned.mesh"), path("same.mesh")});
  EXPECT_EQ(medit.err.find("will not be"), std::string::npos) << medit.err;  // Medit keeps them
  // A VTU pin (tetsmooth:fixed) becomes a Medit RequiredVertex, so it holds
  // through a second conversion; all-zero vertex references are no loss.
  TetMesh vtu_pin = testing::cube_with_centre();
  vtu_pin.fixed.assign(9, 0);
  vtu_pin.fixed[8] = 1;
  write_mesh(vtu_pin, path("pin.vtu"));
  for (const auto& [from, to] : {std::pair{"pin.vtu", "pin.mesh"}, std::pair{"pin.mesh", "pin2.vtu"}}) {
    const CliRun converted = run({"convert", path(from), path(to)});
    EXPECT_EQ(converted.err.find("will not be"), std::string::npos) << converted.err;
    EXPECT_EQ(read_mesh(path(to)).fixed, vtu_pin.fixed) << to;
  }
  // Pins of boundary nodes are no loss to TetGen: the boundary stays fixed.
  TetMesh skin = testing::cube_with_centre();
  skin.fixed.assign(9, 1);
  skin.fixed[8] = 0;
  write_mesh(skin, path("skin.vtu"));
  const CliRun skin_tetgen = run({"convert", path("skin.vtu"), path("skin.node")});
  EXPECT_EQ(skin_tetgen.err.find("pinned"), std::string::npos) << skin_tetgen.err;
  skin.fixed[8] = 1;
  write_mesh(skin, path("skin.vtu"));
  const CliRun centre_tetgen = run({"convert", path("skin.vtu"), path("skin.node")});
  EXPECT_NE(centre_tetgen.err.find("1 pinned node will not be pinned in the tetgen output"), std::string::npos)
      << centre_tetgen.err;
  // Pins on an interface between regions are no loss where the regions
  // stay apart: TetGen and MSH (negative tags renumbered, and named), not
  // .tsm, which keeps no regions.
  TetMesh halves = testing::cube_grid(2);
  halves.fixed.assign(halves.num_nodes(), 1);
  for (std::size_t t = 0; t < halves.num_tets(); ++t) {
    double x = 0;
    for (int k = 0; k < 4; ++k) x += halves.xyz[3 * static_cast<std::size_t>(halves.tets[4 * t + k])];
    halves.extras.tet_tags.push_back(x < 4.0 ? -1 : -2);  // the two halves of the cube, by centroid
  }
  write_mesh(halves, path("halves.vtu"));
  for (const char* kept_regions : {"halves.node", "halves.msh"}) {
    const CliRun r = run({"convert", path("halves.vtu"), path(kept_regions)});
    EXPECT_EQ(r.err.find("pinned"), std::string::npos) << kept_regions << ": " << r.err;
  }
  const CliRun halves_msh = run({"convert", path("halves.vtu"), path("halves2.msh")});
  EXPECT_NE(halves_msh.err.find("negative region tags are written as new positive ones (-2 as 2, -1 as 1): MSH "
                                "physical tags are positive"),
            std::string::npos)
      << halves_msh.err;
  EXPECT_EQ(read_mesh(path("halves2.msh")).extras.tet_tags.front(), 1);
  const CliRun tsm = run({"convert", path("halves.vtu"), path("halves.tsm")});
  EXPECT_NE(tsm.err.find("pinned node"), std::string::npos) << tsm.err;

  TetMesh attrs = testing::cube_with_centre();
  attrs.extras.node_attribute_count = 1;
  attrs.extras.node_attributes.assign(9, 0.5);
  write_mesh(attrs, path("attrs.node"));
  const CliRun vtu = run({"convert", path("attrs.node"), path("attrs.vtu")});
  EXPECT_NE(vtu.err.find("the node attributes (1 per node) will not be written: vtu has no place for them"), std::string::npos)
      << vtu.err;
  std::ofstream(path("ranked.node")) << "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n";
  std::ofstream(path("ranked.ele")) << "1 4 2\n1 1 2 3 4 0.5 9\n";
  const CliRun ranked = run({"convert", path("ranked.node"), path("ranked.mesh")});
  EXPECT_EQ(ranked.code, kExitOk) << ranked.err;
  EXPECT_NE(ranked.err.find("region attribute 0.5 is not a whole number"), std::string::npos) << ranked.err;
  EXPECT_NE(ranked.err.find("the TetGen tet attributes (2 per tet) will not be written: medit keeps only the region "
                            "tags (the first attribute's values where whole, else their ranks)"),
            std::string::npos)
      << ranked.err;
  EXPECT_EQ(read_mesh(path("ranked.mesh")).extras.tet_tags, (std::vector<int>{1}));
  // Medit-only sections are named when the output has no place for them.
  const CliRun ridges = run({"convert", testing::data_path("medit_bipyramid.mesh"), path("bipyramid.vtu")});
  EXPECT_EQ(ridges.code, kExitOk) << ridges.err;
  EXPECT_NE(ridges.err.find("the Medit section Ridges will not be written: vtu has no place for it"),
            std::string::npos)
      << ridges.err;

  // Gmsh element ids that are not just positions survive only in MSH.
  TetMesh ids = testing::cube_with_centre();
  for (std::size_t t = 0; t < ids.num_tets(); ++t) ids.extras.tet_element_tags.push_back(100 + static_cast<long long>(t));
  write_mesh(ids, path("ids.msh"));
  const CliRun to_vtu = run({"convert", path("ids.msh"), path("ids.vtu")});
  EXPECT_NE(to_vtu.err.find("the Gmsh element tags will not be written: vtu numbers them by position"),
            std::string::npos)
      << to_vtu.err;
  const CliRun to_msh = run({"convert", path("ids.msh"), path("ids22.msh"), "--output-format", "msh22"});
  EXPECT_EQ(to_msh.err.find("will not be written"), std::string::npos) << to_msh.err;
  EXPECT_EQ(read_mesh(path("ids22.msh")).extras.tet_element_tags, ids.extras.tet_element_tags);
  // Node tags past the 32-bit ints of field data are named before the work
  // and cost no write: MSH 4.1 keeps them without node fields, 2.2 renumbers.
  TetMesh wide = testing::cube_with_centre();
  for (std::size_t i = 0; i < wide.num_nodes(); ++i) wide.extras.node_tags.push_back(3000000000LL + static_cast<long long>(i));
  write_mesh(wide, path("wide.msh"));
  const CliRun wide41 = run({"smooth", path("wide.msh"), "-o", path("wide-out.msh"), "--device", "cpu"});
  EXPECT_EQ(wide41.code, kExitOk) << wide41.err;
  EXPECT_NE(wide41.err.find("no node field data will be written: MSH names the nodes of field data by 32-bit int and "
                            "node tag 3000000008 is larger"),
            std::string::npos)
      << wide41.err;
  EXPECT_LT(wide41.err.find("will be written"), wide41.err.find("done:")) << wide41.err;
  EXPECT_EQ(read_mesh(path("wide-out.msh")).extras.node_tags, wide.extras.node_tags);
  const CliRun wide22 = run({"convert", path("wide.msh"), path("wide22.msh"), "--output-format", "msh22"});
  EXPECT_EQ(wide22.code, kExitOk) << wide22.err;
  EXPECT_NE(wide22.err.find("the Gmsh node tags will not be written (nodes are numbered 1, 2, ...): MSH 2.2"),
            std::string::npos)
      << wide22.err;
  EXPECT_EQ(read_mesh(path("wide22.msh")).extras.node_tags, (std::vector<long long>{1, 2, 3, 4, 5, 6, 7, 8, 9}));
  // Gmsh physical names have no place in VTU, nor entity tags that split a
  // region in Medit (VTU keeps them as gmsh:geometrical); entity tags that
  // follow the regions lose nothing.
  TetMesh named = testing::cube_with_centre();
  named.extras.tet_tags = {5, 5, 5, 5, 5, 5, 6, 6, 6, 6, 6, 6};
  named.extras.tet_entity_tags = {1, 1, 1, 1, 1, 1, 2, 2, 2, 2, 2, 2};
  named.extras.raw_sections.emplace_back("$PhysicalNames", "2\n3 5 \"soil\"\n3 6 \"rock\"\n");
  write_mesh(named, path("named.msh"));
  const CliRun names = run({"convert", path("named.msh"), path("named.vtu")});
  EXPECT_NE(names.err.find("the Gmsh physical names will not be written: vtu has no place for them"),
            std::string::npos)
      << names.err;
  EXPECT_EQ(names.err.find("entity tags"), std::string::npos) << names.err;
  named.extras.raw_sections.clear();
  named.extras.tet_entity_tags = {1, 1, 1, 1, 1, 3, 2, 2, 2, 2, 2, 2};
  write_mesh(named, path("split.msh"));
  const CliRun split = run({"convert", path("split.msh"), path("split.mesh")});
  EXPECT_NE(split.err.find("the Gmsh entity tags will not be written: medit has no place for them"),
            std::string::npos)
      << split.err;
  const CliRun split_vtu = run({"convert", path("split.msh"), path("split.vtu")});
  EXPECT_EQ(split_vtu.err.find("entity tags"), std::string::npos) << split_vtu.err;
  EXPECT_EQ(read_mesh(path("split.vtu")).extras.tet_entity_tags, named.extras.tet_entity_tags);
  // Boundary patches told apart only by their entity tags are named too.
  TetMesh patches = testing::cube_with_centre();
  patches.extras.blocks.push_back(PassThroughBlock{"triangle", 3, {0, 2, 3, 0, 3, 1}, {}, {7, 8}, {}});
  write_mesh(patches, path("patches.msh"));
  const CliRun patch_medit = run({"convert", path("patches.msh"), path("patches.mesh")});
  EXPECT_NE(patch_medit.err.find("the Gmsh entity tags will not be written"), std::string::npos) << patch_medit.err;
  // Our own MSH numbers nodes and elements 1, 2, ...: nothing to lose.
  write_mesh(testing::cube_with_centre(), path("plain.msh"));
  const CliRun positional = run({"convert", path("plain.msh"), path("plain.vtu")});
  EXPECT_EQ(positional.code, kExitOk) << positional.err;
  EXPECT_EQ(positional.err.find("Gmsh"), std::string::npos) << positional.err;
}

TEST_F(CliFiles, CudaWithoutAGpuExitsWith5) {
  if (cuda_available()) GTEST_SKIP() << "a CUDA device is usable here";
  const std::string in = lattice(2);
  const CliRun r = run({"smooth", in, "-o", path("out.vtu"), "--device", "cuda"});
  EXPECT_EQ(r.code, kExitDevice);
  EXPECT_NE(r.err.find("--device cuda"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("out.vtu")));
}

// --- reports ---------------------------------------------------------------

// "--report -" puts the JSON, alone, on standard output; no file "-".
TEST_F(CliFiles, ReportToStandardOutput) {
  const CliRun r = run({"smooth", lattice(3), "-o", path("out.vtu"), "--device", "cpu", "--report", "-"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["command"], "smooth");
  EXPECT_EQ(j["input"]["nodes"], 64);
  EXPECT_NE(r.err.find("wrote"), std::string::npos) << r.err;  // the summary stays on stderr
  EXPECT_FALSE(fs::exists("-"));
  EXPECT_FALSE(fs::exists(path("-")));
  // Standard output that fails is an output error that names the mesh written.
  std::ostringstream closed, err;
  closed.setstate(std::ios::badbit);
  const int code = run_cli({"smooth", lattice(3), "-o", path("again.vtu"), "--device", "cpu", "-q", "--report", "-"},
                           closed, err, false);
  EXPECT_EQ(code, kExitOutput) << err.str();
  EXPECT_NE(err.str().find("cannot write the report to standard output (the smoothed mesh was written to '" +
                           path("again.vtu") + "')"),
            std::string::npos)
      << err.str();
}

// A report that fails after the mesh was written says so, even with -q:
// the run's result is on disk, only the report is missing.
TEST_F(CliFiles, FailedReportSaysTheMeshWasWritten) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full to fail a write";
  fs::create_symlink("/dev/full", path("full.json"));
  const CliRun r = run({"smooth", lattice(3), "-o", path("out.vtu"), "--device", "cpu", "-q", "--report",
                        path("full.json")});
  EXPECT_EQ(r.code, kExitOutput) << r.err;
  EXPECT_NE(r.err.find("(the smoothed mesh was written to '" + path("out.vtu") + "')"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_regular_file(path("out.vtu")));
}

// Tets of negative signed volume (b-a).((c-a)x(d-a)), counted here rather
// than by the library's quality summary.
std::size_t count_inverted(const TetMesh& m) {
  std::size_t inverted = 0;
  for (std::size_t t = 0; t < m.num_tets(); ++t) {
    const auto at = [&](int k, int c) { return m.xyz[3 * static_cast<std::size_t>(m.tets[4 * t + k]) + c]; };
    double e[3][3];
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c) e[k][c] = at(k + 1, c) - at(0, c);
    const double v6 = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                      e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                      e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
    inverted += v6 < 0;
  }
  return inverted;
}

// Ordinary smoothing moves a node to its neighbours' centroid without
// looking at its star, which in a concave star (the paper's Figure 2)
// inverts a tet. A user who asked for it must be told, on stderr and in the
// report; adaptive smoothing of the same mesh inverts nothing and says
// nothing of the kind.
TEST_F(CliFiles, OrdinarySmoothingThatInvertsTetsSaysSo) {
  write_mesh(testing::concave_star(), path("concave.vtu"));
  const CliRun ordinary = run({"smooth", path("concave.vtu"), "-o", path("ordinary.vtu"), "--device", "cpu",
                               "--method", "ordinary", "--report", path("ordinary.json")});
  ASSERT_EQ(ordinary.code, kExitOk) << ordinary.err;
  const std::size_t inverted = count_inverted(read_mesh(path("ordinary.vtu")));
  ASSERT_GT(inverted, 0u) << "the fixture no longer inverts under ordinary smoothing";
  const std::string warning = "ordinary smoothing inverted " + std::to_string(inverted) +
                              " tets; --method adaptive with the coloured strategy or --form A never does";
  EXPECT_NE(ordinary.err.find("tetsmooth: warning: " + warning + "\n"), std::string::npos) << ordinary.err;
  nlohmann::json j;
  std::ifstream(path("ordinary.json")) >> j;
  EXPECT_EQ(j["warnings"], nlohmann::json::array({warning}));

  const CliRun adaptive = run({"smooth", path("concave.vtu"), "-o", path("adaptive.vtu"), "--device", "cpu"});
  ASSERT_EQ(adaptive.code, kExitOk) << adaptive.err;
  EXPECT_EQ(count_inverted(read_mesh(path("adaptive.vtu"))), 0u);
  EXPECT_EQ(adaptive.err.find("warning"), std::string::npos) << adaptive.err;
}

// The inversion warning counts the tets smoothing inverted, not those the
// input already had: a concave star that ordinary smoothing inverts, beside
// a separate tet that is inverted from the start (all its nodes are on the
// boundary, so it stays as it is).
TEST_F(CliFiles, InversionWarningCountsOnlyTheTetsSmoothingInverted) {
  TetMesh mesh = testing::concave_star();
  const index_t first = static_cast<index_t>(mesh.num_nodes());
  const double far[4][3] = {{10, 0, 0}, {11, 0, 0}, {10, 1, 0}, {10, 0, 1}};
  for (const auto& p : far) mesh.xyz.insert(mesh.xyz.end(), {p[0], p[1], p[2]});
  mesh.tets.insert(mesh.tets.end(), {first, first + 2, first + 1, first + 3});  // two nodes swapped: inverted
  write_mesh(mesh, path("in.vtu"));
  ASSERT_EQ(count_inverted(read_mesh(path("in.vtu"))), 1u);
  const CliRun r = run({"smooth", path("in.vtu"), "-o", path("out.vtu"), "--device", "cpu", "--method", "ordinary"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const std::size_t inverted_after = count_inverted(read_mesh(path("out.vtu")));
  ASSERT_GT(inverted_after, 1u) << "the fixture no longer inverts under ordinary smoothing";
  EXPECT_NE(r.err.find("ordinary smoothing inverted " + std::to_string(inverted_after - 1) + " tets;"),
            std::string::npos)
      << r.err;
}

// Tets put right do not hide tets inverted: beside the concave star, a cube
// whose centre lies outside it (its 2 tets on the face x = 1 inverted),
// which ordinary smoothing moves back to the corners' centroid. A net count
// said nothing where the two were equal.
TEST_F(CliFiles, InversionWarningCountsTetsInvertedAndPutRightApart) {
  TetMesh mesh = testing::concave_star();
  const std::size_t star_tets = mesh.num_tets();
  const TetMesh cube = testing::cube_with_centre(1.5, 0.5, 0.5);
  const index_t first = static_cast<index_t>(mesh.num_nodes());
  for (std::size_t i = 0; i < cube.xyz.size(); ++i) mesh.xyz.push_back(cube.xyz[i] + (i % 3 == 0 ? 10.0 : 0.0));
  for (const index_t v : cube.tets) mesh.tets.push_back(first + v);
  write_mesh(mesh, path("in.vtu"));
  const std::size_t inverted_before = count_inverted(read_mesh(path("in.vtu")));
  ASSERT_EQ(inverted_before, 2u);
  const CliRun r = run({"smooth", path("in.vtu"), "-o", path("out.vtu"), "--device", "cpu", "--method", "ordinary"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const TetMesh out = read_mesh(path("out.vtu"));
  TetMesh cube_part = out;
  cube_part.tets.erase(cube_part.tets.begin(), cube_part.tets.begin() + static_cast<std::ptrdiff_t>(4 * star_tets));
  ASSERT_EQ(count_inverted(cube_part), 0u) << "the cube's tets are not all put right";
  const std::size_t made = count_inverted(out);  // all of them in the star
  ASSERT_GT(made, 0u) << "the fixture no longer inverts under ordinary smoothing";
  EXPECT_NE(r.err.find("ordinary smoothing inverted " + std::to_string(made) +
                       " tets (and put right 2 that the input had inverted);"),
            std::string::npos)
      << r.err;
}

// The report's total covers every phase it lists (it is measured from the
// start of the run to the end of the write), and the write is timed: a
// phase left unset reads 0, while writing a file on steady_clock's
// nanosecond ticks never takes 0 (no bound on how long it takes).
TEST_F(CliFiles, ReportTotalCoversItsPhases) {
  const CliRun r = run({"smooth", lattice(3), "-o", path("out.vtu"), "--device", "cpu", "--report",
                        path("report.json")});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  nlohmann::json j;
  std::ifstream(path("report.json")) >> j;
  const auto& t = j["timings_ms"];
  double phases = 0;
  for (const char* phase : {"read", "topology", "colouring", "smoothing", "write"}) phases += t[phase].get<double>();
  EXPECT_GE(t["total"].get<double>(), phases) << t.dump();
  EXPECT_GT(t["write"].get<double>(), 0.0) << t.dump();
}

// Zero-volume tets are neither inverted nor fine: both reports count them
// under their own name. Two flat tets (five nodes in the plane z = 3) beside
// a cube, so the count differs from every other count of the report (no
// inverted, unreferenced or repeated tet).
TEST_F(CliFiles, ReportsCountDegenerateTets) {
  TetMesh mesh = testing::cube_with_centre();
  const index_t first = static_cast<index_t>(mesh.num_nodes());
  const double in_plane[5][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {2, 0}};
  for (const auto& p : in_plane) mesh.xyz.insert(mesh.xyz.end(), {p[0], p[1], 3.0});
  mesh.tets.insert(mesh.tets.end(), {first, first + 1, first + 2, first + 3, first + 1, first + 4, first + 3, first + 2});
  write_mesh(mesh, path("flat.vtu"));

  const CliRun r = run({"smooth", path("flat.vtu"), "-o", path("out.vtu"), "--device", "cpu", "--report",
                        path("report.json")});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  EXPECT_NE(r.err.find("2 degenerate tets (zero volume or a repeated node)"), std::string::npos) << r.err;
  nlohmann::json j;
  std::ifstream(path("report.json")) >> j;
  EXPECT_EQ(j["input"]["tets"], 14);
  EXPECT_EQ(j["input"]["degenerate_tets"], 2);
  EXPECT_EQ(j["input"]["inverted_tets"], 0);
  EXPECT_EQ(j["quality"]["before"]["degenerate"], 2);
  EXPECT_EQ(j["quality"]["after"]["degenerate"], 2);  // their nodes are all on the boundary

  const CliRun q = run({"quality", path("flat.vtu"), "--json"});
  ASSERT_EQ(q.code, kExitOk) << q.err;
  const nlohmann::json quality = nlohmann::json::parse(q.out);
  EXPECT_EQ(quality["input"]["degenerate_tets"], 2);
  EXPECT_EQ(quality["quality"]["degenerate"], 2);
}

TEST_F(CliFiles, SmoothReportJsonCarriesOptionsCountsAndQuality) {
  const std::string in = lattice(4);
  const CliRun r = run({"smooth", in, "-o", path("out.vtu"), "--device", "cpu", "--threads", "2", "--max-iter", "50",
                        "--report", path("report.json")});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  nlohmann::json j;
  std::ifstream(path("report.json")) >> j;

  EXPECT_EQ(j["command"], "smooth");
  EXPECT_EQ(j["options"]["method"], "adaptive");
  EXPECT_EQ(j["options"]["form"], "B");
  EXPECT_EQ(j["options"]["threads"], 2);
  EXPECT_EQ(j["options"]["max_iterations"], 50);
  EXPECT_EQ(j["options"]["cpu_ordering"], "coloured");
  EXPECT_EQ(j["device"], "cpu");
  EXPECT_EQ(j["backend"], "cpu-threads");
  EXPECT_EQ(j["input"]["nodes"], 125);
  EXPECT_EQ(j["input"]["tets"], 6 * 64);
  EXPECT_EQ(j["input"]["format"], "vtu");

  const int sweeps = j["sweeps"];
  EXPECT_GE(sweeps, 1);
  EXPECT_LE(sweeps, 50);
  EXPECT_EQ(j["accepted_per_sweep"].size(), static_cast<std::size_t>(sweeps));
  EXPECT_EQ(j["max_displacement_per_sweep"].size(), static_cast<std::size_t>(sweeps));
  EXPECT_TRUE(j["stop_reason"].is_string());
  EXPECT_EQ(j["movable_nodes"], 27);  // the 3^3 interior nodes of a 4^3 lattice
  EXPECT_GT(j["colours"].get<int>(), 1);
  for (const char* phase : {"read", "topology", "colouring", "smoothing", "write", "total"})
    EXPECT_GE(j["timings_ms"][phase].get<double>(), 0.0) << phase;

  const auto& before = j["quality"]["before"];
  const auto& after = j["quality"]["after"];
  for (const auto* s : {&before, &after}) {
    const std::vector<std::size_t> counts = (*s)["histogram"]["counts"];
    EXPECT_EQ(counts.size(), 10u);
    EXPECT_EQ(std::accumulate(counts.begin(), counts.end(), std::size_t{0}), 6u * 64u);
    EXPECT_EQ((*s)["tets"], 6 * 64);
  }
  // The adaptive method only accepts moves that raise a node's worst tet.
  EXPECT_GE(after["min"].get<double>(), before["min"].get<double>());
  EXPECT_EQ(after["inverted"], 0);

  // The human report on stderr: the same numbers in a before/after table.
  EXPECT_NE(r.err.find("before"), std::string::npos);
  EXPECT_NE(r.err.find("after"), std::string::npos);
  EXPECT_NE(r.err.find("radius ratio histogram"), std::string::npos);
  EXPECT_NE(r.err.find("on cpu (2 thread(s)"), std::string::npos) << r.err;
}

// The histogram's bins are named by their lower edges, 0 to 0.9 (a bin
// holds lower <= q < lower + 0.1; the last one also holds q = 1).
TEST_F(CliFiles, QualityJsonHistogramNamesLowerEdges) {
  const CliRun r = run({"quality", lattice(2), "--json"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const std::vector<double> edges = nlohmann::json::parse(r.out)["quality"]["histogram"]["lower_edges"];
  const std::vector<double> expected{0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9};
  ASSERT_EQ(edges.size(), expected.size());
  for (std::size_t k = 0; k < edges.size(); ++k) EXPECT_DOUBLE_EQ(edges[k], expected[k]) << k;
}

// A Gmsh input is reported as "msh" whichever Gmsh format it was read as
// (the reader takes 2.2 and 4.1 alike): --format msh22 too, not "msh22".
TEST_F(CliFiles, GmshInputOfEitherVersionIsNamedMsh) {
  write_mesh(testing::cube_with_centre(), path("v22.msh"), MeshFormat::Msh22);
  for (const std::vector<std::string>& format :
       {std::vector<std::string>{}, std::vector<std::string>{"--format", "msh22"},
        std::vector<std::string>{"--format", "msh41"}}) {
    std::vector<std::string> args{"quality", path("v22.msh"), "--json"};
    args.insert(args.end(), format.begin(), format.end());
    const CliRun r = run(args);
    ASSERT_EQ(r.code, kExitOk) << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out)["input"]["format"], "msh") << (format.empty() ? "" : format[1]);
  }
}

// Form A's conflict repair undoes some accepted moves (12 on this lattice);
// the report counts them as the summary on stderr does. Its "device" is the
// one the run used, beside the one asked for in "options".
TEST_F(CliFiles, ReportCountsRevertedMovesAndNamesTheDeviceUsed) {
  const CliRun r = run({"smooth", lattice(3), "-o", path("out.vtu"), "--form", "A", "--report", path("report.json")});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  nlohmann::json j;
  std::ifstream(path("report.json")) >> j;
  const long long reverted = j["reverted_moves"];
  EXPECT_GT(reverted, 0) << "the fixture no longer reverts moves";
  EXPECT_NE(r.err.find(", " + std::to_string(reverted) + " moves reverted"), std::string::npos) << r.err;
  EXPECT_EQ(j["options"]["device"], "auto");
  EXPECT_EQ(j["device"], cuda_available() ? "cuda" : "cpu");
}

// The report's colour count is the run's: the one the summary on stderr
// gives.
TEST_F(CliFiles, ReportColoursAreTheSummarys) {
  const CliRun r = run({"smooth", lattice(3), "-o", path("out.vtu"), "--device", "cpu", "--report",
                        path("report.json")});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  nlohmann::json j;
  std::ifstream(path("report.json")) >> j;
  EXPECT_NE(r.err.find(", " + std::to_string(j["colours"].get<int>()) + " colours"), std::string::npos) << r.err;
}

// A volume in two physical groups, as Gmsh's MSH 2.2 writer saves it: every
// tet twice, under two tags. The run says so, counts the repeats, and the
// boundary stays put: read as a mesh without boundary, it would all move.
TEST_F(CliFiles, RepeatedTetsAreNamedAndKeepTheBoundary) {
  TetMesh mesh = read_mesh(lattice(4));
  const std::size_t nt = mesh.num_tets();
  mesh.extras.tet_tags.assign(nt, 1);
  for (std::size_t t = 0; t < nt; ++t) {
    mesh.tets.insert(mesh.tets.end(), {mesh.tets[4 * t], mesh.tets[4 * t + 1], mesh.tets[4 * t + 2],
                                       mesh.tets[4 * t + 3]});
    mesh.extras.tet_tags.push_back(2);
  }
  write_mesh(mesh, path("twice.msh"), MeshFormat::Msh22);
  const CliRun r = run({"smooth", path("twice.msh"), "-o", path("out.msh"), "--device", "cpu", "--report",
                        path("report.json")});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  EXPECT_NE(r.err.find("384 tets repeat the nodes of an earlier tet"), std::string::npos) << r.err;
  nlohmann::json j;
  std::ifstream(path("report.json")) >> j;
  EXPECT_EQ(j["input"]["repeated_tets"], 384);
  EXPECT_EQ(j["movable_nodes"], 27);

  const TetMesh out = read_mesh(path("out.msh"));
  ASSERT_EQ(out.num_nodes(), mesh.num_nodes());
  const std::vector<index_t> listed_once(mesh.tets.begin(), mesh.tets.begin() + 4 * nt);
  const std::vector<std::uint8_t> boundary = find_boundary_nodes(listed_once, mesh.num_nodes());
  std::size_t moved = 0;
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i)
    for (int c = 0; c < 3; ++c) {
      if (boundary[i]) {
        EXPECT_EQ(out.xyz[3 * i + c], mesh.xyz[3 * i + c]) << "boundary node " << i;
      }
      moved += out.xyz[3 * i + c] != mesh.xyz[3 * i + c];
    }
  EXPECT_GT(moved, 0u);
}

// Coordinates so large or so small that the radius ratio leaves double's
// range: a warning says so, for the mesh units in which it reads q = 0.
TEST_F(CliFiles, CoordinatesBeyondTheRadiusRatiosRangeAreNamed) {
  for (double scale : {1e40, 1e-40, 1.0}) {
    TetMesh mesh = testing::cube_with_centre();
    for (double& x : mesh.xyz) x *= scale;
    write_mesh(mesh, path("scaled.vtu"));
    const CliRun r = run({"quality", path("scaled.vtu")});
    EXPECT_EQ(r.code, kExitOk);
    EXPECT_EQ(r.err.find("the nodes span") != std::string::npos, scale != 1.0) << scale << ": " << r.err;
  }
}

// Every tet inverted: the warning points at the file's orientation.
// A single inverted tet is the usual tangle and worth a warning as much as
// many; the warning says whether this run's method may make it worse.
TEST_F(CliFiles, OneInvertedTetIsWarnedWithWhatTheMethodDoesToIt) {
  TetMesh mesh = testing::cube_with_centre();
  std::swap(mesh.tets[0], mesh.tets[1]);
  write_mesh(mesh, path("one.vtu"));
  const CliRun adaptive = run({"smooth", path("one.vtu"), "-o", path("a.vtu"), "--device", "cpu"});
  EXPECT_EQ(adaptive.code, kExitOk) << adaptive.err;
  EXPECT_NE(adaptive.err.find("1 inverted tet (negative volume); continuing: adaptive smoothing never makes it "
                              "worse"),
            std::string::npos)
      << adaptive.err;
  const CliRun ordinary =
      run({"smooth", path("one.vtu"), "-o", path("o.vtu"), "--device", "cpu", "--method", "ordinary"});
  EXPECT_NE(ordinary.err.find("1 inverted tet (negative volume); continuing, but ordinary smoothing may make it "
                              "worse"),
            std::string::npos)
      << ordinary.err;
}

// The input warnings for `mesh` read from "m.vtu", a line each.
std::string input_warnings_text(const TetMesh& mesh) {
  std::string all;
  for (const std::string& w : input_warnings(mesh, inspect_input(mesh, "m.vtu"), "m.vtu")) all += w + "\n";
  return all;
}

// One repeated tet, one degenerate tet and one loose node are warned about
// as much as many: a single stray element is the usual case in a hand-edited
// file.
TEST(CliPieces, SingleRepeatedTetDegenerateTetAndLooseNodeAreWarned) {
  TetMesh mesh = testing::cube_with_centre();
  mesh.tets.insert(mesh.tets.end(), mesh.tets.begin(), mesh.tets.begin() + 4);
  mesh.tets.insert(mesh.tets.end(), {0, 0, 1, 2});  // a repeated node: zero volume
  mesh.xyz.insert(mesh.xyz.end(), {9, 9, 9});
  const std::string all = input_warnings_text(mesh);
  EXPECT_NE(all.find("m.vtu: 1 tet repeats the nodes of an earlier tet"), std::string::npos) << all;
  EXPECT_NE(all.find("m.vtu: 1 node belongs to no tet; it is kept as it is"), std::string::npos) << all;
  EXPECT_NE(all.find("m.vtu: 1 degenerate tet (zero volume"), std::string::npos) << all;
}

// The scale warning names the span, so the user knows how far to scale.
TEST(CliPieces, HugeSpanIsNamedWithItsSize) {
  TetMesh mesh = testing::regular_tet();
  for (double& x : mesh.xyz) x *= 3e40;
  const std::string all = input_warnings_text(mesh);
  EXPECT_NE(all.find("m.vtu: the nodes span 3e+40 units"), std::string::npos) << all;
}

// The span is measured between the nodes, not from the origin: a tet of
// unit edges scaled to 1e-40 and moved to 1e-30 spans 1e-40, too small for
// the radius ratio, though its coordinates reach 1e-30.
TEST(CliPieces, SpanIsMeasuredBetweenTheNodesNotFromTheOrigin) {
  TetMesh mesh = testing::regular_tet();
  for (double& x : mesh.xyz) x = 1e-30 + x * 1e-40;
  const std::string all = input_warnings_text(mesh);
  EXPECT_NE(all.find("m.vtu: the nodes span 1e-40 units"), std::string::npos) << all;
}

// The scale warning is for spans a double cannot handle; a mesh whose nodes
// all coincide spans 0, which is degenerate (warned as such), not tiny.
TEST(CliPieces, ZeroSpanIsNotCalledTooSmall) {
  TetMesh mesh = testing::regular_tet();
  for (double& x : mesh.xyz) x = 1;
  const std::string all = input_warnings_text(mesh);
  EXPECT_NE(all.find("degenerate"), std::string::npos) << all;
  EXPECT_EQ(all.find("span"), std::string::npos) << all;
}

TEST_F(CliFiles, AllTetsInvertedSuggestsTheOppositeOrientation) {
  TetMesh mesh = testing::cube_with_centre();
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) std::swap(mesh.tets[4 * t], mesh.tets[4 * t + 1]);
  write_mesh(mesh, path("flipped.vtu"));
  const CliRun r = run({"quality", path("flipped.vtu")});
  EXPECT_EQ(r.code, kExitOk);
  EXPECT_NE(r.err.find("12 inverted tets (negative volume), all of them: the file probably lists each tet's nodes in "
                       "the opposite order"),
            std::string::npos)
      << r.err;
  std::swap(mesh.tets[0], mesh.tets[1]);  // one tet right again: a tangle, not a convention
  write_mesh(mesh, path("tangled.vtu"));
  const CliRun tangled = run({"quality", path("tangled.vtu")});
  EXPECT_NE(tangled.err.find("11 inverted tets"), std::string::npos) << tangled.err;
  EXPECT_EQ(tangled.err.find("opposite order"), std::string::npos) << tangled.err;
}

// File names are bytes, not always UTF-8: the reports still come out, with
// the bad byte replaced, and the mesh is written.
TEST_F(CliFiles, ReportsSurviveFileNamesThatAreNotUtf8) {
  const std::string in = lattice(2, "bad\xff.vtu");
  const CliRun r = run({"smooth", in, "-o", path("out.vtu"), "--device", "cpu", "-q", "--report", path("r.json")});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  nlohmann::json j;
  std::ifstream(path("r.json")) >> j;
  EXPECT_EQ(j["input"]["path"], path("bad\xef\xbf\xbd.vtu"));
  const CliRun q = run({"quality", in, "--json"});
  ASSERT_EQ(q.code, kExitOk) << q.err;
  EXPECT_EQ(nlohmann::json::parse(q.out)["input"]["nodes"], 27);
}

// Two layers told apart only by their tets' tags: the interface between
// them stays put, the run says so, and the written file gains no pins.
// The note "N nodes on interfaces ... stay fixed" counts what the pins add:
// interface nodes on the boundary, or that the file had already fixed, are
// not added again. The file's own pins come back when the pins end.
TEST(CliPieces, InterfacePinsCountOnlyNodesTheFileLeftFree) {
  TetMesh mesh = testing::cube_grid(4, 0.2);
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) {
    double cx = 0;
    for (int k = 0; k < 4; ++k) cx += mesh.xyz[3 * static_cast<std::size_t>(mesh.tets[4 * t + k])] / 4;
    mesh.extras.tet_tags.push_back(cx < 2 ? 1 : 2);
  }
  // The 5 x 5 nodes of the grid column x = 2 (jittered) are the interface,
  // 3 x 3 of them off the boundary; the file pins 3 of those and one on the
  // boundary.
  mesh.fixed.assign(mesh.num_nodes(), 0);
  const auto inside = [](double c) { return c > 0.5 && c < 3.5; };
  std::size_t pinned_inside = 0;
  bool pinned_on_boundary = false;
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i) {
    if (!(mesh.xyz[3 * i] > 1.5 && mesh.xyz[3 * i] < 2.5)) continue;
    const bool off_boundary = inside(mesh.xyz[3 * i + 1]) && inside(mesh.xyz[3 * i + 2]);
    if (off_boundary && pinned_inside < 3) mesh.fixed[i] = 1, ++pinned_inside;
    if (!off_boundary && !pinned_on_boundary) mesh.fixed[i] = 1, pinned_on_boundary = true;
  }
  ASSERT_EQ(pinned_inside, 3u);
  ASSERT_TRUE(pinned_on_boundary);
  const std::vector<std::uint8_t> file_pins = mesh.fixed;
  {
    const SmoothingPins pins(mesh, 2);
    EXPECT_EQ(pins.added_on_interfaces(), 9u - 3u);
    EXPECT_EQ(pins.added_on_features(), 0u);
  }
  EXPECT_EQ(mesh.fixed, file_pins);
}

TEST_F(CliFiles, MaterialInterfacesStayFixed) {
  TetMesh mesh = testing::cube_grid(4, 0.2);
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) {
    double cx = 0;
    for (int k = 0; k < 4; ++k) cx += mesh.xyz[3 * static_cast<std::size_t>(mesh.tets[4 * t + k])] / 4;
    mesh.extras.tet_tags.push_back(cx < 2 ? 1 : 2);  // the cubes left and right of x = 2
  }
  write_mesh(mesh, path("layers.vtu"));
  const CliRun r = run({"smooth", path("layers.vtu"), "-o", path("out.vtu"), "--device", "cpu"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  // The plane's 9 nodes off the boundary: the others stay fixed anyway.
  EXPECT_NE(r.err.find("9 nodes on interfaces between regions"), std::string::npos) << r.err;
  const TetMesh out = read_mesh(path("out.vtu"));
  EXPECT_TRUE(out.fixed.empty());
  EXPECT_EQ(out.extras.tet_tags, mesh.extras.tet_tags);
  std::size_t moved = 0;
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i) {
    const bool on_interface = mesh.xyz[3 * i] > 1.5 && mesh.xyz[3 * i] < 2.5;  // node column i = 2, jittered
    for (int c = 0; c < 3; ++c) {
      if (on_interface) {
        EXPECT_EQ(out.xyz[3 * i + c], mesh.xyz[3 * i + c]) << "interface node " << i;
      }
      moved += out.xyz[3 * i + c] != mesh.xyz[3 * i + c];
    }
  }
  EXPECT_GT(moved, 0u);
  const CliRun q = run({"quality", path("layers.vtu"), "--json"});
  ASSERT_EQ(q.code, kExitOk) << q.err;
  EXPECT_EQ(nlohmann::json::parse(q.out)["input"]["movable_nodes"], 27 - 9);
}

// A second-order mesh with one curved interior edge: the run says how many
// tets keep their shape and how many corners that pins, `quality` counts
// them out of the movable nodes, the written mesh is second-order again,
// and Medit output is refused before any work, leaving no file.
TEST_F(CliFiles, CurvedSecondOrderTetsKeepTheirShape) {
  TetMesh mesh = testing::with_midsides(testing::cube_grid(4, 0.2));
  // The edge between grid nodes (1,1,1) and (2,1,1): node i + 5 j + 25 k.
  const index_t a = 1 + 5 + 25, b = 2 + 5 + 25;
  std::set<index_t> corners;
  std::size_t bent = 0;
  for (std::size_t t = 0; t < mesh.num_tets(); ++t)
    for (int e = 0; e < 6; ++e) {
      const index_t u = mesh.tets[4 * t + kTetEdges[e][0]], v = mesh.tets[4 * t + kTetEdges[e][1]];
      if (std::min(u, v) != a || std::max(u, v) != b) continue;
      mesh.xyz[3 * static_cast<std::size_t>(mesh.midsides[6 * t + static_cast<std::size_t>(e)]) + 2] += 0.1;
      corners.insert(&mesh.tets[4 * t], &mesh.tets[4 * t] + 4);
      ++bent;
    }
  ASSERT_GT(bent, 0u);
  // Of the bent tets' corners, those inside the lattice: 1 <= i, j, k <= 3.
  const auto inside = [](index_t i) { return i >= 1 && i <= 3; };
  std::size_t interior = 0;
  for (index_t n : corners) interior += inside(n % 5) && inside(n / 5 % 5) && inside(n / 25);
  write_mesh(mesh, path("curved.msh"));
  const CliRun r =
      run({"smooth", path("curved.msh"), "-o", path("out.vtu"), "--device", "cpu", "--report", path("r.json")});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  std::ifstream report(path("r.json"));
  const nlohmann::json smoothed = nlohmann::json::parse(report)["input"];
  EXPECT_EQ(smoothed["nodes_per_tet"], 10);
  EXPECT_EQ(smoothed["curved_tets"], bent);
  const std::string note = std::to_string(bent) + " second-order tets have curved edges and keep their shape: " +
                           std::to_string(interior) + " corner nodes off the boundary stay fixed";
  EXPECT_NE(r.err.find(note), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("belong to no tet"), std::string::npos) << r.err;  // midside nodes are used
  const TetMesh out = read_mesh(path("out.vtu"));
  EXPECT_EQ(out.midsides, mesh.midsides);
  const CliRun q = run({"quality", path("curved.msh"), "--json"});
  ASSERT_EQ(q.code, kExitOk) << q.err;
  const nlohmann::json input = nlohmann::json::parse(q.out)["input"];
  EXPECT_EQ(input["movable_nodes"], 27 - interior);
  EXPECT_EQ(input["nodes_per_tet"], 10);
  EXPECT_EQ(input["curved_tets"], bent);
  // The boundary's midside nodes count with its 98 corners, as in the field.
  const std::vector<std::uint8_t> boundary = find_boundary_nodes(mesh.tets, mesh.num_nodes(), 1, mesh.midsides);
  EXPECT_EQ(input["boundary_nodes"], std::count(boundary.begin(), boundary.end(), 1));
  EXPECT_GT(input["boundary_nodes"], 98);

  const CliRun medit = run({"smooth", path("curved.msh"), "-o", path("out.mesh"), "--device", "cpu"});
  EXPECT_EQ(medit.code, kExitOutput);
  EXPECT_NE(medit.err.find("Medit output holds 4-node tets only"), std::string::npos) << medit.err;
  EXPECT_FALSE(fs::exists(path("out.mesh")));
}

// Coloured is a Form B scheme: Form A defaults to MultiBlock, and asking for
// both is refused at parsing, whatever the device, before any reading.
TEST(CliParse, FormAFollowsWithMultiBlockAndRefusesColoured) {
  const auto a = parse_as<SmoothCommand>({"smooth", "in.vtu", "-o", "out.vtu", "--form", "A"});
  EXPECT_EQ(a.options.strategy, Strategy::MultiBlock);
  EXPECT_FALSE(a.strategy_given);
  const auto single = parse_as<SmoothCommand>({"smooth", "in.vtu", "-o", "o.vtu", "--form", "A", "--strategy",
                                               "singleblock"});
  EXPECT_EQ(single.options.strategy, Strategy::SingleBlock);
  const std::string e = usage_error_of({"smooth", "in.vtu", "-o", "o.vtu", "--strategy", "coloured", "--form", "A"});
  EXPECT_NE(e.find("--strategy coloured"), std::string::npos) << e;
  EXPECT_NE(e.find("--form A use multiblock or singleblock"), std::string::npos) << e;
  EXPECT_EQ(run({"smooth", "no-such-file.vtu", "-o", "o.vtu", "--form", "A", "--strategy", "coloured"}).code,
            kExitUsage);
}

// OUT may be IN: the run warns, and the file is replaced by the whole result.
TEST_F(CliFiles, SmoothingInPlaceWarnsAndReplacesTheInput) {
  const std::string in = lattice(3, "lattice.msh");
  const TetMesh before = read_mesh(in);
  const CliRun r = run({"smooth", in, "-o", in, "--device", "cpu"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  EXPECT_NE(r.err.find("warning: " + in + " is the input mesh: it will be replaced once the whole result is written"),
            std::string::npos)
      << r.err;
  const TetMesh after = read_mesh(in);
  EXPECT_EQ(after.tets, before.tets);
  EXPECT_NE(after.xyz, before.xyz);
  EXPECT_EQ(files(), std::vector<std::string>{"lattice.msh"});  // no temporary left
  // Another file, or another spelling of one: warned only where it is the input.
  const CliRun other = run({"convert", in, path("copy.vtu")});
  EXPECT_EQ(other.err.find("is the input mesh"), std::string::npos) << other.err;
  const CliRun spelled = run({"convert", in, (dir_ / "." / "lattice.msh").string()});
  EXPECT_NE(spelled.err.find("is the input mesh"), std::string::npos) << spelled.err;
}

// The stop line says why a run ended in the terms of its method.
TEST_F(CliFiles, StopLineFitsTheRun) {
  write_mesh(testing::regular_tet(), path("one.vtu"));
  const CliRun none = run({"smooth", path("one.vtu"), "-o", path("one_out.vtu"), "--device", "cpu"});
  ASSERT_EQ(none.code, kExitOk) << none.err;
  EXPECT_NE(none.err.find("done: 1 sweep(s), nothing to smooth: no movable nodes"), std::string::npos) << none.err;
  const std::string in = lattice(3);
  const CliRun ordinary = run({"smooth", in, "-o", path("o.vtu"), "--device", "cpu", "--method", "ordinary",
                               "--max-iter", "2", "--tol", "0"});
  ASSERT_EQ(ordinary.code, kExitOk) << ordinary.err;
  EXPECT_NE(ordinary.err.find("done: 2 sweep(s), reached --max-iter\n"), std::string::npos) << ordinary.err;
  const CliRun adaptive = run({"smooth", in, "-o", path("a.vtu"), "--device", "cpu", "--max-iter", "1", "--tol", "0"});
  ASSERT_EQ(adaptive.code, kExitOk) << adaptive.err;
  EXPECT_NE(adaptive.err.find("done: 1 sweep(s), reached --max-iter; more sweeps may improve further"),
            std::string::npos)
      << adaptive.err;
}

TEST_F(CliFiles, QuietPrintsNothingOnSuccess) {
  const std::string in = lattice(3);
  const CliRun r = run({"smooth", in, "-o", path("out.mesh"), "--device", "cpu", "-q"});
  EXPECT_EQ(r.code, kExitOk);
  EXPECT_TRUE(r.err.empty()) << r.err;
  EXPECT_TRUE(r.out.empty());
  EXPECT_TRUE(fs::exists(path("out.mesh")));
}

// -q silences warnings too, not only notes: an input that warns (a node of
// no tet) leaves stderr empty with -q, and names the node without it.
TEST_F(CliFiles, QuietSilencesInputWarnings) {
  TetMesh mesh = testing::cube_with_centre();
  mesh.xyz.insert(mesh.xyz.end(), {5.0, 5.0, 5.0});
  write_mesh(mesh, path("loose.vtu"));
  const CliRun loud = run({"quality", path("loose.vtu")});
  ASSERT_EQ(loud.code, kExitOk) << loud.err;
  EXPECT_NE(loud.err.find("tetsmooth: warning: "), std::string::npos) << "the fixture no longer warns";
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"quality", path("loose.vtu"), "-q"},
        std::vector<std::string>{"smooth", path("loose.vtu"), "-o", path("out.vtu"), "--device", "cpu", "-q"},
        std::vector<std::string>{"convert", path("loose.vtu"), path("out.mesh"), "-q"}}) {
    const CliRun r = run(args);
    EXPECT_EQ(r.code, kExitOk) << args[0] << ": " << r.err;
    EXPECT_TRUE(r.err.empty()) << args[0] << ": " << r.err;
  }
}

TEST_F(CliFiles, IgnoredCpuOptionsAreNamedInAWarning) {
  const std::string in = lattice(2);
  const CliRun r = run({"smooth", in, "-o", path("out.vtu"), "--device", "cpu", "--strategy", "multiblock"});
  EXPECT_EQ(r.code, kExitOk);
  EXPECT_NE(r.err.find("tetsmooth: warning: --strategy"), std::string::npos) << r.err;
}

// generate's note names the seed it used and the mesh's quality: min and
// mean as `quality` measures them on the written file; the seed is used.
TEST_F(CliFiles, GenerateNoteNamesItsSeedAndQuality) {
  const CliRun r = run({"generate", "lattice-2", "-o", path("l.vtu"), "--seed", "5"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  EXPECT_NE(r.err.find("lattice-2 (seed 5), 27 nodes, 48 tets"), std::string::npos) << r.err;
  const CliRun q = run({"quality", path("l.vtu"), "--json"});
  ASSERT_EQ(q.code, kExitOk) << q.err;
  const nlohmann::json j = nlohmann::json::parse(q.out);
  const std::string expected = "radius ratio min " + quality_text(j["quality"]["min"].get<double>()) + " mean " +
                               quality_text(j["quality"]["mean"].get<double>()) + " (vtu)";
  EXPECT_NE(r.err.find(expected), std::string::npos) << expected << "\n" << r.err;
  // Another seed, another jitter.
  ASSERT_EQ(run({"generate", "lattice-2", "-o", path("m.vtu"), "--seed", "6", "-q"}).code, kExitOk);
  EXPECT_NE(read_mesh(path("l.vtu")).xyz, read_mesh(path("m.vtu")).xyz);
}

// convert's note names the format read and the format written.
TEST_F(CliFiles, ConvertNoteNamesBothFormats) {
  write_mesh(testing::cube_with_centre(), path("in.mesh"));
  const CliRun r = run({"convert", path("in.mesh"), path("out.vtu")});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  EXPECT_NE(r.err.find("(medit -> vtu)"), std::string::npos) << r.err;
}

TEST_F(CliFiles, QualityJsonListsTheWorstTetsWorstFirst) {
  const std::string in = lattice(3);
  const CliRun r = run({"quality", in, "--json", "--worst", "4"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["index_base"], 0);
  EXPECT_EQ(j["input"]["nodes"], 64);
  EXPECT_EQ(j["input"]["tets"], 6 * 27);
  EXPECT_EQ(j["input"]["movable_nodes"], 8);
  EXPECT_EQ(j["input"]["boundary_nodes"], 64 - 8);
  const auto& worst = j["worst_tets"];
  ASSERT_EQ(worst.size(), 4u);
  EXPECT_DOUBLE_EQ(worst[0]["quality"].get<double>(), j["quality"]["min"].get<double>());
  for (std::size_t k = 1; k < worst.size(); ++k)
    EXPECT_LE(worst[k - 1]["quality"].get<double>(), worst[k]["quality"].get<double>());
  for (const auto& t : worst) {
    EXPECT_LT(t["tet"].get<int>(), 6 * 27);
    for (const auto& n : t["nodes"]) EXPECT_LT(n.get<int>(), 64);
  }
}

// A mesh whose nodes are all on the boundary has no movable tets, so no
// minimum over them: no value, not the 1 the minimum starts from.
TEST_F(CliFiles, NoMovableTetsGiveNoMinimumOverThem) {
  write_mesh(testing::regular_tet(), path("one.vtu"));
  const CliRun json = run({"quality", path("one.vtu"), "--json"});
  ASSERT_EQ(json.code, kExitOk) << json.err;
  const nlohmann::json j = nlohmann::json::parse(json.out);
  EXPECT_TRUE(j["quality"]["min_movable"].is_null()) << j["quality"];
  EXPECT_EQ(j["quality"]["movable_tets"], 0);
  const CliRun text = run({"quality", path("one.vtu")});
  EXPECT_NE(text.out.find("min over movable tets                  -\n"), std::string::npos) << text.out;
}

// The run's summary on stderr: how many of all the nodes may move, and on
// how many CPU threads (0, the default, is every core; 1 is one thread),
// and why no GPU was used when the CLI chose the device.
TEST_F(CliFiles, SmoothSummaryNamesMovableNodesAndThreads) {
  const std::string in = lattice(4);  // 125 nodes, the 3^3 interior ones movable
  const CliRun all = run({"smooth", in, "-o", path("all.vtu"), "--device", "cpu"});
  ASSERT_EQ(all.code, kExitOk) << all.err;
  EXPECT_NE(all.err.find("  27 of 125 nodes movable"), std::string::npos) << all.err;
  EXPECT_NE(all.err.find("on cpu (all cores"), std::string::npos) << all.err;
  const CliRun one = run({"smooth", in, "-o", path("one.vtu"), "--device", "cpu", "--threads", "1"});
  ASSERT_EQ(one.code, kExitOk) << one.err;
  EXPECT_NE(one.err.find("on cpu (1 thread(s)"), std::string::npos) << one.err;
  // Why no GPU was used is said when the CLI chose (auto), not when the user did.
  EXPECT_EQ(all.err.find("no GPU used"), std::string::npos) << all.err;
  if (cuda_available()) return;
  const CliRun chosen = run({"smooth", in, "-o", path("auto.vtu")});
  ASSERT_EQ(chosen.code, kExitOk) << chosen.err;
  EXPECT_NE(chosen.err.find("; no GPU used: "), std::string::npos) << chosen.err;
}

// Nodes pinned on a material interface are neither boundary nodes nor
// movable: `quality` counts the two apart. A 4^3 grid split at x = 2 has
// 98 boundary nodes of 125 and 27 interior ones, 9 of them on the interface.
TEST_F(CliFiles, QualityCountsInterfaceNodesAsNeitherBoundaryNorMovable) {
  TetMesh mesh = testing::cube_grid(4, 0.2);
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) {
    double cx = 0;
    for (int k = 0; k < 4; ++k) cx += mesh.xyz[3 * static_cast<std::size_t>(mesh.tets[4 * t + k])] / 4;
    mesh.extras.tet_tags.push_back(cx < 2 ? 1 : 2);
  }
  write_mesh(mesh, path("layers.vtu"));
  const CliRun json = run({"quality", path("layers.vtu"), "--json"});
  ASSERT_EQ(json.code, kExitOk) << json.err;
  const nlohmann::json j = nlohmann::json::parse(json.out);
  EXPECT_EQ(j["input"]["boundary_nodes"], 98);
  EXPECT_EQ(j["input"]["movable_nodes"], 18);
  const CliRun text = run({"quality", path("layers.vtu")});
  ASSERT_EQ(text.code, kExitOk) << text.err;
  EXPECT_NE(text.out.find("125 nodes (98 on the boundary, 18 movable)"), std::string::npos) << text.out;
}

TEST_F(CliFiles, QualityTextStatesIndexBase) {
  const std::string in = lattice(2);
  const CliRun r = run({"quality", in, "--worst", "2"});
  ASSERT_EQ(r.code, kExitOk) << r.err;
  EXPECT_NE(r.out.find("2 worst tets (0-based tet and node indices)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("radius ratio histogram"), std::string::npos);
}

TEST_F(CliFiles, WorstTetsGiveTheFilesOwnNumbers) {
  // Gmsh numbers the deck's 44 triangles first, so its tets are elements
  // 45, 46, ...; its nodes are 1, 2, ..., which the indices already give.
  const std::string in = testing::data_path("abaqus_gmsh_layers.inp");
  const CliRun text = run({"quality", in, "--worst", "1"});
  ASSERT_EQ(text.code, kExitOk) << text.err;
  const CliRun json = run({"quality", in, "--json", "--worst", "3"});
  ASSERT_EQ(json.code, kExitOk) << json.err;
  const nlohmann::json worst = nlohmann::json::parse(json.out)["worst_tets"];
  ASSERT_EQ(worst.size(), 3u);
  for (const auto& t : worst) {
    EXPECT_EQ(t["element_number"].get<long long>(), t["tet"].get<long long>() + 45);
    EXPECT_FALSE(t.contains("node_numbers"));
  }
  EXPECT_NE(text.out.find("   (in the file: element " + std::to_string(worst[0]["element_number"].get<long long>()) + ")\n"),
            std::string::npos)
      << text.out;
}

// --- pieces ----------------------------------------------------------------

// The library throws InputError without a file for a mesh too large for its
// tables; on_input_mesh names the input file, keeps the message and the type
// (exit 3), and passes a step's result through.
TEST(CliPieces, MeshWideInputErrorsNameTheInputFile) {
  EXPECT_EQ(on_input_mesh("big.vtu", [] { return 7; }), 7);
  try {
    on_input_mesh("big.vtu", []() -> int { throw InputError("", "too many nodes for 32-bit indices"); });
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "big.vtu: too many nodes for 32-bit indices");
  }
}

TEST(CliPieces, WorstTetsPicksTheLowestQualitiesWithTheirNodes) {
  TetMesh mesh = testing::cube_with_centre();
  const std::vector<double> q{0.5, 0.1, 0.9, 0.1, 0.3, 0.7, 0.8, 0.6, 0.2, 0.4, 0.95, 0.99};
  const std::vector<RankedTet> worst = worst_tets(mesh, q, 3);
  ASSERT_EQ(worst.size(), 3u);
  EXPECT_EQ(worst[0].tet, 1);  // ties go to the lower index
  EXPECT_EQ(worst[1].tet, 3);
  EXPECT_EQ(worst[2].tet, 8);
  EXPECT_DOUBLE_EQ(worst[2].quality, 0.2);
  for (int c = 0; c < 4; ++c) EXPECT_EQ(worst[1].nodes[c], mesh.tets[4 * 3 + c]);
  EXPECT_EQ(worst[1].element, 0);  // the file numbers nothing
  EXPECT_EQ(worst[1].node_numbers[0], 0);
  EXPECT_EQ(worst_tets(mesh, q, 100).size(), q.size());
  // With numbers of the file's own, the file's numbers too; numbers that are
  // just the positions 1, 2, ... add nothing to the indices.
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) mesh.extras.tet_element_tags.push_back(100 + static_cast<long long>(t));
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i) mesh.extras.node_tags.push_back(static_cast<long long>(i) + 1);
  const RankedTet numbered = worst_tets(mesh, q, 2)[1];
  EXPECT_EQ(numbered.element, 103);
  EXPECT_EQ(numbered.node_numbers[0], 0);
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i) mesh.extras.node_tags[i] += 10;
  for (int c = 0; c < 4; ++c) EXPECT_EQ(worst_tets(mesh, q, 2)[1].node_numbers[c], mesh.tets[4 * 3 + c] + 11);
}

// The histogram has ten bins of 0.1 up to q = 1 inclusive: the top bin holds
// the best tets and must be there with its count and its full bar.
TEST(CliPieces, HistogramShowsTheTopBin) {
  QualitySummary s;
  s.histogram = {0, 0, 0, 0, 0, 0, 0, 0, 0, 7};
  std::ostringstream os;
  write_histogram(os, {{"", &s}});
  // A single column's largest bin fills the whole bar of 44 marks.
  EXPECT_NE(os.str().find("  0.9-1.0           7 " + std::string(44, '#') + "\n"), std::string::npos) << os.str();
}

// Each row of the table shows its own value: poor, inverted and degenerate
// tets are different things (a poor tet is not inverted), as are min, mean
// and max.
TEST(CliPieces, QualityTableRowsShowTheirOwnValues) {
  QualitySummary s;
  s.min = 0.125;
  s.mean = 0.5;
  s.max = 0.875;
  s.below_0_1 = 3000;
  s.inverted = 1;
  s.degenerate = 20;
  std::ostringstream os;
  write_quality_table(os, {{"", &s}});
  const std::string text = os.str();
  // A row: the label left-aligned in 28 columns, the value right-aligned in 12.
  const auto row = [](const std::string& label, const std::string& value) {
    return "  " + label + std::string(28 - label.size(), ' ') + std::string(12 - value.size(), ' ') + value + "\n";
  };
  EXPECT_NE(text.find(row("tets with q < 0.1", "3,000")), std::string::npos) << text;
  EXPECT_NE(text.find(row("inverted tets", "1")), std::string::npos) << text;
  EXPECT_NE(text.find(row("degenerate tets", "20")), std::string::npos) << text;
  EXPECT_NE(text.find(row("radius ratio  min", "0.1250")), std::string::npos) << text;
  EXPECT_NE(text.find(row("              mean", "0.5000")), std::string::npos) << text;
  EXPECT_NE(text.find(row("              max", "0.8750")), std::string::npos) << text;
  // Two columns are told apart by their titles, in a header line.
  std::ostringstream two;
  write_quality_table(two, {{"before", &s}, {"after", &s}});
  EXPECT_EQ(two.str().rfind("  " + std::string(28, ' ') + "      before       after\n", 0), 0u) << two.str();
}

TEST(CliPieces, HistogramBarsShareOneScale) {
  QualitySummary a, b;
  a.histogram = {0, 0, 0, 0, 0, 0, 0, 0, 100, 0};
  b.histogram = {1, 0, 0, 0, 0, 0, 0, 0, 50, 0};
  std::ostringstream os;
  write_histogram(os, {{"before", &a}, {"after", &b}});
  const std::string text = os.str();
  EXPECT_NE(text.find(std::string(22, '#')), std::string::npos);  // the largest bin fills its bar
  EXPECT_NE(text.find(" 50 " + std::string(11, '#')), std::string::npos) << text;
  // A single tet still shows, since isolated slivers are what one looks for.
  std::istringstream lines(text);
  std::string line;
  bool saw_first_bin = false;
  while (std::getline(lines, line))
    if (line.rfind("  0.0-0.1", 0) == 0) {
      saw_first_bin = true;
      EXPECT_NE(line.find(" 1 #"), std::string::npos) << line;
    }
  EXPECT_TRUE(saw_first_bin);
}

// Qualities are shown with four decimals; only values too small to show
// that way switch to scientific notation, negative ones (inverted tets)
// included, and an exact zero stays "0.0000".
// With no worst tets to list (quality --worst 0, or an empty mesh) the text
// report has no table header announcing "0 worst tets".
TEST(CliPieces, NoWorstTetsWriteNothing) {
  std::ostringstream os;
  write_worst_tets(os, {});
  EXPECT_EQ(os.str(), "");
}

TEST(CliPieces, QualityTextKeepsTinyValuesOfEitherSign) {
  EXPECT_EQ(quality_text(0.0), "0.0000");
  EXPECT_EQ(quality_text(0.25), "0.2500");
  EXPECT_EQ(quality_text(-0.25), "-0.2500");
  EXPECT_EQ(quality_text(-1.0), "-1.0000");
  EXPECT_EQ(quality_text(2e-6), "2.00e-06");
  EXPECT_EQ(quality_text(-2e-6), "-2.00e-06");
}

TEST(CliPieces, ThousandsSeparators) {
  EXPECT_EQ(with_thousands(0), "0");
  EXPECT_EQ(with_thousands(999), "999");
  EXPECT_EQ(with_thousands(1000), "1,000");
  EXPECT_EQ(with_thousands(1234567), "1,234,567");
}

// A progress report whose quality pass returns `q` and takes `cost` of
// `clock` (a test's own time), counting its calls.
SweepProgress report_with_quality(int sweep, std::int64_t accepted, MinMeanQuality q,
                                  ProgressLine::Clock::time_point& clock, ProgressLine::Clock::duration cost,
                                  int& calls) {
  SweepProgress p{sweep, accepted, 0.5, {}};
  p.quality = [q, &clock, cost, &calls] {
    ++calls;
    clock += cost;
    return q;
  };
  return p;
}

// A terminal has no "clear to end of line" here: a shorter line drawn over a
// longer one must be padded with spaces, or the tail of the old one stays;
// at the end the line is blanked, not merely returned to.
TEST(CliPieces, ProgressLinePadsOverALongerPreviousLine) {
  using std::chrono::milliseconds;
  ProgressLine::Clock::time_point clock{};
  const auto now = [&clock] { return clock; };
  int calls = 0;
  std::ostringstream os;
  ProgressLine line(os, ProgressLine::Style::Redraw, 10, milliseconds(0), milliseconds(0), now);
  line.update(report_with_quality(1, 1234567, {0.0123456, 0.61234}, clock, milliseconds(0), calls));
  const std::size_t long_width = os.str().size() - 1;  // without its '\r'
  line.update(report_with_quality(2, 5, {0.5, 0.5}, clock, milliseconds(0), calls));
  const std::string second = os.str().substr(long_width + 1);
  const std::string text = "\r  sweep 2/10  moved 5 up to 0.5  q min 0.5  mean 0.5";
  ASSERT_LT(text.size(), long_width + 1);
  EXPECT_EQ(second, text + std::string(long_width + 1 - text.size(), ' '));
  // Finishing blanks the line it drew and returns to its start, so that the
  // next message does not land after the progress text.
  const std::size_t before_finish = os.str().size();
  line.finish();
  EXPECT_EQ(os.str().substr(before_finish), "\r" + std::string(text.size() - 1, ' ') + "\r");
}

TEST(CliPieces, ProgressLineRedrawsInPlaceAndErasesItself) {
  using std::chrono::milliseconds;
  ProgressLine::Clock::time_point clock{};
  const auto now = [&clock] { return clock; };
  int calls = 0;
  std::ostringstream os;
  ProgressLine line(os, ProgressLine::Style::Redraw, 10, milliseconds(0), milliseconds(0), now);
  line.update(report_with_quality(3, 1234, {0.0123456, 0.61234}, clock, milliseconds(0), calls));
  EXPECT_EQ(os.str(), "\r  sweep 3/10  moved 1,234 up to 0.5  q min 0.0123  mean 0.612");
  EXPECT_EQ(calls, 1);
  // The line stays within 79 columns: whole with the numbers of a 10M-node
  // run, without the cap for larger ones, cut short for the largest.
  const auto drawn = [&](int sweep, int max_sweeps, std::int64_t moved) {
    std::ostringstream wide;
    ProgressLine big(wide, ProgressLine::Style::Redraw, max_sweeps, milliseconds(0), milliseconds(0), now);
    int passes = 0;
    SweepProgress p = report_with_quality(sweep, moved, {-1.23456e-05, -0.61234}, clock, milliseconds(0), passes);
    p.max_displacement = 1.23456e-05;
    big.update(p);
    EXPECT_LE(wide.str().size(), 1u + ProgressLine::kWidth) << wide.str();
    return wide.str();
  };
  static_assert(ProgressLine::kWidth < 80);
  EXPECT_EQ(drawn(100, 100, 12345678), "\r  sweep 100/100  moved 12,345,678 up to 1.23e-05  q min -1.23e-05  mean -0.612");
  EXPECT_EQ(drawn(100000, 100000, 123456789),
            "\r  sweep 100000  moved 123,456,789 up to 1.23e-05  q min -1.23e-05  mean -0.612");
  const std::string largest = drawn(2147483647, 2147483647, 9223372036854775807);
  EXPECT_EQ(largest.size(), 1u + ProgressLine::kWidth);
  EXPECT_EQ(largest.rfind("\r  sweep 2147483647  moved 9,223,372,036,854,775,807 up to 1.23e-05  q min", 0), 0u);
  line.finish();
  EXPECT_EQ(os.str().back(), '\r');
  EXPECT_EQ(os.str().find('\n'), std::string::npos);

  std::ostringstream silent;
  ProgressLine off(silent, ProgressLine::Style::Off, 10, milliseconds(0), milliseconds(0), now);
  off.update(report_with_quality(1, 1, {0.5, 0.5}, clock, milliseconds(0), calls));
  off.finish();
  EXPECT_TRUE(silent.str().empty());
  EXPECT_EQ(calls, 1) << "a disabled line runs no quality pass";
}

// --progress: redraws on a terminal unless never or -q; log lines where
// stderr is not a terminal only when asked for, whole lines ten seconds
// apart at least, with nothing to erase.
TEST(CliPieces, ProgressLineStylesForLogsAndTerminals) {
  using Style = ProgressLine::Style;
  EXPECT_EQ(ProgressLine::style_for(ProgressMode::Auto, true, false), Style::Redraw);
  EXPECT_EQ(ProgressLine::style_for(ProgressMode::Auto, false, false), Style::Off);
  EXPECT_EQ(ProgressLine::style_for(ProgressMode::Always, true, false), Style::Redraw);
  EXPECT_EQ(ProgressLine::style_for(ProgressMode::Always, false, false), Style::Lines);
  EXPECT_EQ(ProgressLine::style_for(ProgressMode::Never, true, false), Style::Off);
  EXPECT_EQ(ProgressLine::style_for(ProgressMode::Always, false, true), Style::Off);
  EXPECT_EQ(ProgressLine::style_for(ProgressMode::Auto, true, true), Style::Off);
  EXPECT_GE(ProgressLine::interval_for(Style::Lines), std::chrono::seconds(10));

  using std::chrono::milliseconds;
  ProgressLine::Clock::time_point clock{};
  std::ostringstream log;
  ProgressLine lines(log, Style::Lines, 20, milliseconds(0), milliseconds(1000), [&clock] { return clock; });
  int calls = 0;
  lines.update(report_with_quality(1, 5, {0.25, 0.5}, clock, milliseconds(0), calls));
  clock += milliseconds(500);
  lines.update(report_with_quality(2, 4, {0.25, 0.5}, clock, milliseconds(0), calls));
  clock += milliseconds(500);
  lines.update(report_with_quality(3, 3, {0.3, 0.5}, clock, milliseconds(0), calls));
  lines.finish();
  EXPECT_EQ(log.str(),
            "  sweep 1/20  moved 5 up to 0.5  q min 0.25  mean 0.5\n"
            "  sweep 3/20  moved 3 up to 0.5  q min 0.3  mean 0.5\n");
  EXPECT_EQ(calls, 2);
}

TEST(CliPieces, ProgressLineSkipsReportsWithoutQuality) {
  using std::chrono::milliseconds;
  ProgressLine::Clock::time_point clock{};
  std::ostringstream os;
  ProgressLine line(os, ProgressLine::Style::Redraw, 10, milliseconds(0), milliseconds(0), [&clock] { return clock; });
  line.update(SweepProgress{1, 5, 0.25, {}});  // a CUDA report before the last of its check
  EXPECT_TRUE(os.str().empty());
  int calls = 0;
  line.update(report_with_quality(2, 7, {0.25, 0.5}, clock, milliseconds(0), calls));
  EXPECT_EQ(os.str().rfind("\r  sweep 2/10  moved 7 up to", 0), 0u) << os.str();
}

TEST(CliPieces, ProgressLineWaitsTheDelayAndPacesItsQualityPasses) {
  using std::chrono::milliseconds;
  ProgressLine::Clock::time_point clock{};
  std::ostringstream os;
  ProgressLine line(os, ProgressLine::Style::Redraw, 100, milliseconds(500), milliseconds(100), [&clock] { return clock; });
  int calls = 0;
  const MinMeanQuality q{0.25, 0.5};
  line.update(report_with_quality(1, 1, q, clock, milliseconds(40), calls));
  EXPECT_EQ(calls, 0) << "nothing before the delay";
  clock += milliseconds(500);
  line.update(report_with_quality(2, 1, q, clock, milliseconds(40), calls));
  EXPECT_EQ(calls, 1);
  // That pass took 40 ms, so the next waits 800 ms, not the 100 ms interval.
  static_assert(ProgressLine::kPacing == 20);
  clock += milliseconds(700);
  line.update(report_with_quality(3, 1, q, clock, milliseconds(40), calls));
  EXPECT_EQ(calls, 1);
  clock += milliseconds(100);
  line.update(report_with_quality(4, 1, q, clock, milliseconds(1), calls));
  EXPECT_EQ(calls, 2);
  EXPECT_NE(os.str().find("sweep 4/100"), std::string::npos) << os.str();
  EXPECT_EQ(os.str().find("sweep 3/100"), std::string::npos) << os.str();
  // A cheap pass brings the interval back.
  clock += milliseconds(100);
  line.update(report_with_quality(5, 1, q, clock, milliseconds(1), calls));
  EXPECT_EQ(calls, 3);
}

// The refusal says which of the usual mistakes it is: a directory that is
// not there (a typo in the path) or a file where a directory should be.
TEST_F(CliFiles, OutputCheckNamesWhyTheDirectoryWillNotDo) {
  const auto why = [](const std::string& p) {
    try {
      check_output_location(p);
    } catch (const OutputError& e) {
      return std::string(e.what());
    }
    return std::string("no OutputError");
  };
  const std::string missing = why(path("missing/x.vtu"));
  EXPECT_NE(missing.find("directory '" + path("missing") + "' does not exist"), std::string::npos) << missing;
  std::ofstream(path("file")) << "x";
  const std::string file = why(path("file/x.vtu"));
  EXPECT_NE(file.find("'" + path("file") + "' is not a directory"), std::string::npos) << file;
}

TEST_F(CliFiles, OutputCheckRejectsDirectoriesAndMissingParents) {
  EXPECT_THROW(check_output_location(path("")), OutputError);
  EXPECT_THROW(check_output_location(path("missing/x.vtu")), OutputError);
  std::ofstream(path("file")) << "x";
  EXPECT_THROW(check_output_location(path("file/x.vtu")), OutputError);
  EXPECT_NO_THROW(check_output_location(path("fine.vtu")));
  // Where links lead: into a missing directory, or round in a cycle.
  std::filesystem::create_symlink("missing/x.vtu", path("dangling.vtu"));
  EXPECT_THROW(check_output_location(path("dangling.vtu")), OutputError);
  std::filesystem::create_symlink("fine_b.vtu", path("loop_a.vtu"));
  std::filesystem::create_symlink("loop_a.vtu", path("fine_b.vtu"));
  EXPECT_THROW(check_output_location(path("loop_a.vtu")), OutputError);
  std::filesystem::create_symlink("fine.vtu", path("to_fine.vtu"));
  EXPECT_NO_THROW(check_output_location(path("to_fine.vtu")));
}

}  // namespace
}  // namespace tetsmooth::cli
