// Format names and extensions, read_mesh/write_mesh dispatch for every
// format, and the atomic-write helper every writer goes through.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <thread>

#include "mesh/errors.hpp"
#include "mesh/io/atomic_file.hpp"
#include "mesh/io/mesh_io.hpp"
#include "support/scratch_dir.hpp"
#include "support/test_meshes.hpp"

namespace tetsmooth {
namespace {

namespace fs = std::filesystem;

class IoDir : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::size_t files() const { return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir_), {})); }

  testing::ScratchDir scratch_{"io"};
  const fs::path dir_ = scratch_.path();
};

std::string contents(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(Formats, ParseFormatNames) {
  EXPECT_EQ(parse_format("tetgen"), MeshFormat::TetGen);
  EXPECT_EQ(parse_format("vtu"), MeshFormat::Vtu);
  EXPECT_EQ(parse_format("VTK"), MeshFormat::Vtk);
  EXPECT_EQ(parse_format("msh"), MeshFormat::Msh41);
  EXPECT_EQ(parse_format("msh41"), MeshFormat::Msh41);
  EXPECT_EQ(parse_format("msh41-binary"), MeshFormat::Msh41Binary);
  EXPECT_EQ(parse_format("msh22"), MeshFormat::Msh22);
  EXPECT_EQ(parse_format("medit"), MeshFormat::Medit);
  EXPECT_EQ(parse_format("tsm"), MeshFormat::Cache);
  EXPECT_EQ(parse_format("auto"), MeshFormat::Auto);
  try {
    parse_format("stl");
    FAIL() << "no UsageError";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("'stl'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("msh41-binary"), std::string::npos) << e.what();
  }
}

TEST(Formats, NamesParseBack) {
  for (MeshFormat f : {MeshFormat::Auto, MeshFormat::TetGen, MeshFormat::Vtu, MeshFormat::Vtk, MeshFormat::Msh41,
                       MeshFormat::Msh41Binary, MeshFormat::Msh22, MeshFormat::Medit, MeshFormat::Cache})
    EXPECT_EQ(parse_format(format_name(f)), f) << format_name(f);
}

TEST(Formats, FromPathExtensions) {
  EXPECT_EQ(format_from_path("a/box.node"), MeshFormat::TetGen);
  EXPECT_EQ(format_from_path("box.ele"), MeshFormat::TetGen);
  EXPECT_EQ(format_from_path("box.vtu"), MeshFormat::Vtu);
  EXPECT_EQ(format_from_path("BOX.VTK"), MeshFormat::Vtk);
  EXPECT_EQ(format_from_path("box.msh"), MeshFormat::Msh41);
  EXPECT_EQ(format_from_path("box.mesh"), MeshFormat::Medit);
  EXPECT_EQ(format_from_path("run.1/box.tsm"), MeshFormat::Cache);
  EXPECT_EQ(format_from_path("box.vtu", MeshFormat::Msh22), MeshFormat::Msh22);  // an explicit format wins
  EXPECT_THROW(format_from_path("box.stl"), UsageError);
  EXPECT_THROW(format_from_path("run.1/box"), UsageError);
  EXPECT_THROW(format_from_path("box"), UsageError);
}

class RoundTrip : public IoDir, public ::testing::WithParamInterface<MeshFormat> {};

TEST_P(RoundTrip, WriteThenReadGivesTheSameMesh) {
  const MeshFormat format = GetParam();
  const TetMesh mesh = testing::cube_grid(3, 0.25);
  const char* ext = format == MeshFormat::TetGen  ? ".node"
                    : format == MeshFormat::Vtu   ? ".vtu"
                    : format == MeshFormat::Vtk   ? ".vtk"
                    : format == MeshFormat::Medit ? ".mesh"
                    : format == MeshFormat::Cache ? ".tsm"
                                                  : ".msh";
  const std::string file = path(std::string("m") + ext);
  write_mesh(mesh, file, format);
  const TetMesh back = read_mesh(file);  // extension (and for MSH the header) decides
  EXPECT_EQ(back.tets, mesh.tets);
  ASSERT_EQ(back.xyz.size(), mesh.xyz.size());
  // Every writer is meant to round-trip doubles exactly; allow the last bit
  // for text writers that print max_digits10 rather than the shortest form.
  for (std::size_t i = 0; i < mesh.xyz.size(); ++i)
    EXPECT_NEAR(back.xyz[i], mesh.xyz[i], 4e-16 * std::abs(mesh.xyz[i])) << "coordinate " << i;
}

INSTANTIATE_TEST_SUITE_P(Formats, RoundTrip,
                         ::testing::Values(MeshFormat::TetGen, MeshFormat::Vtu, MeshFormat::Vtk, MeshFormat::Msh41,
                                           MeshFormat::Msh41Binary, MeshFormat::Msh22, MeshFormat::Medit,
                                           MeshFormat::Cache),
                         [](const ::testing::TestParamInfo<MeshFormat>& p) {
                           std::string name = format_name(p.param);
                           name.erase(std::remove(name.begin(), name.end(), '-'), name.end());
                           return name;
                         });

TEST_F(IoDir, TetGenBaseNameIsRecognised) {
  const TetMesh mesh = testing::cube_with_centre();
  write_mesh(mesh, path("box.ele"));
  EXPECT_TRUE(fs::exists(path("box.node")));
  EXPECT_EQ(read_mesh(path("box")).tets, mesh.tets);
}

TEST_F(IoDir, MissingInputNamesThePath) {
  try {
    read_mesh(path("absent.vtu"));
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("absent.vtu: cannot open"), std::string::npos) << e.what();
  }
}

TEST_F(IoDir, AtomicWriteReplacesTheTargetAndLeavesNoTemporary) {
  write_atomically(path("t.txt"), [](std::ostream& out) { out << "old"; });
  write_atomically(path("t.txt"), [](std::ostream& out) { out << "new contents"; });
  EXPECT_EQ(contents(path("t.txt")), "new contents");
  EXPECT_EQ(files(), 1u);
}

TEST_F(IoDir, AtomicWriteKeepsTheTargetWhenTheBodyThrows) {
  write_atomically(path("t.txt"), [](std::ostream& out) { out << "old"; });
  EXPECT_THROW(write_atomically(path("t.txt"),
                                [](std::ostream& out) {
                                  out << std::string(1 << 20, 'x');  // more than one buffer reaches the file
                                  throw std::logic_error("body failed");
                                }),
               std::logic_error);
  EXPECT_EQ(contents(path("t.txt")), "old");
  EXPECT_EQ(files(), 1u);
}

TEST_F(IoDir, AtomicGroupWritesNothingUnlessEveryBodySucceeds) {
  write_atomically(path("a.node"), [](std::ostream& out) { out << "old a"; });
  EXPECT_THROW(write_atomically({{path("a.node"), [](std::ostream& out) { out << "new a"; }},
                                 {path("a.ele"), [](std::ostream&) { throw std::runtime_error("second failed"); }}}),
               std::runtime_error);
  EXPECT_EQ(contents(path("a.node")), "old a");
  EXPECT_FALSE(fs::exists(path("a.ele")));
  EXPECT_EQ(files(), 1u);
}

// A directory in the way of the second file: the first is not replaced
// either, so a TetGen pair is never left half new.
TEST_F(IoDir, AtomicGroupChecksEveryTargetBeforeReplacingAny) {
  write_atomically(path("a.node"), [](std::ostream& out) { out << "old a"; });
  fs::create_directory(path("a.ele"));
  EXPECT_THROW(write_atomically({{path("a.node"), [](std::ostream& out) { out << "new a"; }},
                                 {path("a.ele"), [](std::ostream& out) { out << "new ele"; }}}),
               OutputError);
  EXPECT_EQ(contents(path("a.node")), "old a");
  EXPECT_TRUE(fs::is_directory(path("a.ele")));
  EXPECT_EQ(files(), 2u);
}

TEST_F(IoDir, AtomicWriteIntoMissingDirectoryNamesPathAndReason) {
  try {
    write_atomically(path("no/such/dir/t.txt"), [](std::ostream& out) { out << "x"; });
    FAIL() << "no OutputError";
  } catch (const OutputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("no/such/dir/t.txt"), std::string::npos) << msg;
    EXPECT_NE(msg.find("No such file or directory"), std::string::npos) << msg;
  }
}

TEST_F(IoDir, AtomicWriteOverADirectoryFailsCleanly) {
  fs::create_directory(path("taken"));
  try {
    write_atomically(path("taken"), [](std::ostream& out) { out << "x"; });
    FAIL() << "no OutputError";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("taken"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_directory(path("taken")));
  EXPECT_EQ(files(), 1u);
}

TEST_F(IoDir, AtomicWriteReportsABadStream) {
  try {
    write_atomically(path("t.txt"), [](std::ostream& out) { out.setstate(std::ios::failbit); });
    FAIL() << "no OutputError";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("t.txt"), std::string::npos) << e.what();
  }
  EXPECT_EQ(files(), 0u);
}

// A link to the real file: the file is replaced, the link stays a link, and
// no temporary is left in either directory.
TEST_F(IoDir, AtomicWriteFollowsSymbolicLinks) {
  fs::create_directory(path("real"));
  write_atomically(path("real/t.txt"), [](std::ostream& out) { out << "old"; });
  fs::create_symlink("real/t.txt", path("link.txt"));  // relative to the link's directory
  write_atomically(path("link.txt"), [](std::ostream& out) { out << "new"; });
  EXPECT_TRUE(fs::is_symlink(path("link.txt")));
  EXPECT_EQ(contents(path("real/t.txt")), "new");
  EXPECT_EQ(files(), 2u);
  EXPECT_EQ(std::distance(fs::directory_iterator(path("real")), fs::directory_iterator{}), 1);
  // A dangling link: the file it names is created.
  fs::create_symlink(path("real/later.txt"), path("dangling.txt"));
  write_atomically(path("dangling.txt"), [](std::ostream& out) { out << "made"; });
  EXPECT_TRUE(fs::is_symlink(path("dangling.txt")));
  EXPECT_EQ(contents(path("real/later.txt")), "made");
  // Links in a cycle name no file: refused as open() refuses them, both
  // links left as they were and no temporary.
  fs::create_symlink("loop_b.txt", path("loop_a.txt"));
  fs::create_symlink("loop_a.txt", path("loop_b.txt"));
  EXPECT_TRUE(follow_links(path("loop_a.txt")).endless);
  EXPECT_FALSE(follow_links(path("link.txt")).endless);
  EXPECT_EQ(follow_links(path("link.txt")).path, path("real/t.txt"));
  try {
    write_atomically(path("loop_a.txt"), [](std::ostream& out) { out << "lost"; });
    ADD_FAILURE() << "a write through a cycle of links succeeded";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find(std::strerror(ELOOP)), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_symlink(path("loop_a.txt")));
  EXPECT_TRUE(fs::is_symlink(path("loop_b.txt")));
  EXPECT_EQ(files(), 5u);  // real/, link.txt, dangling.txt and the two links
}

TEST_F(IoDir, AtomicWriteKeepsTheModeOfTheFileItReplaces) {
  write_atomically(path("t.txt"), [](std::ostream& out) { out << "old"; });
  fs::permissions(path("t.txt"), fs::perms::owner_read | fs::perms::owner_write);
  write_atomically(path("t.txt"), [](std::ostream& out) { out << "new"; });
  EXPECT_EQ(fs::status(path("t.txt")).permissions(), fs::perms::owner_read | fs::perms::owner_write);
  EXPECT_EQ(contents(path("t.txt")), "new");
}

// A FIFO (like /dev/stdout in a pipeline) is written into, not replaced.
TEST_F(IoDir, AtomicWriteIntoAFifoWritesThrough) {
  ASSERT_EQ(::mkfifo(path("pipe").c_str(), 0600), 0);
  // Opened for reading first and without blocking, so the write below finds
  // a reader; its few bytes fit in the pipe's buffer.
  const int reader = ::open(path("pipe").c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  write_atomically(path("pipe"), [](std::ostream& out) { out << "through the pipe"; });
  char buf[64] = {};
  const ssize_t n = ::read(reader, buf, sizeof buf - 1);
  ::close(reader);
  EXPECT_EQ(std::string(buf, n > 0 ? static_cast<std::size_t>(n) : 0), "through the pipe");
  EXPECT_EQ(fs::status(path("pipe")).type(), fs::file_type::fifo);
  EXPECT_EQ(files(), 1u);
}

// A full disk is reported by its errno (/dev/full fails every write with
// ENOSPC), not as a stream that merely went bad: the user learns why.
TEST_F(IoDir, AtomicWriteReportsTheErrnoOfAFailedWrite) {
  if (::access("/dev/full", W_OK) != 0) GTEST_SKIP() << "no writable /dev/full";
  try {
    write_atomically("/dev/full", [](std::ostream& out) { out << std::string(1 << 17, 'x'); });
    FAIL() << "no OutputError";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find(std::strerror(ENOSPC)), std::string::npos) << e.what();
  }
}

// A chain of 40 links is followed to its file; one of 41 is refused as
// endless, as open() counts (the Linux limit, 40, for a path of links).
TEST_F(IoDir, AtomicWriteFollowsFortyLinksButNotFortyOne) {
  write_atomically(path("end.txt"), [](std::ostream& out) { out << "old"; });
  std::string next = "end.txt";
  for (int k = 1; k <= 41; ++k) {
    const std::string name = "link" + std::to_string(k);
    fs::create_symlink(next, path(name));
    next = name;
  }
  EXPECT_EQ(follow_links(path("link40")).path, path("end.txt"));
  EXPECT_FALSE(follow_links(path("link40")).endless);
  EXPECT_TRUE(follow_links(path("link41")).endless);
  write_atomically(path("link40"), [](std::ostream& out) { out << "new"; });
  EXPECT_EQ(contents(path("end.txt")), "new");
  EXPECT_TRUE(fs::is_symlink(path("link40")));
}

// A link into /proc (as /dev/stdout is, to /proc/self/fd/1) names a file
// this process holds open: it is appended to in place, after what was
// written through the descriptor, not replaced by a new file that the
// descriptor would no longer reach.
TEST_F(IoDir, AtomicWriteThroughAHeldFileAppendsInPlace) {
  const int fd = ::open(path("held.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::write(fd, "head ", 5), 5);
  struct stat before {};
  ASSERT_EQ(::fstat(fd, &before), 0);
  fs::create_symlink("/proc/self/fd/" + std::to_string(fd), path("out"));
  ASSERT_TRUE(follow_links(path("out")).held);
  write_atomically(path("out"), [](std::ostream& out) { out << "body"; });
  struct stat after {};
  ASSERT_EQ(::stat(path("held.txt").c_str(), &after), 0);
  ::close(fd);
  EXPECT_EQ(after.st_ino, before.st_ino) << "the held file was replaced";
  EXPECT_EQ(contents(path("held.txt")), "head body");
  EXPECT_EQ(files(), 2u);  // held.txt and the link, no temporary
}

// /dev/fd/N and /proc/self/fd/N name a descriptor's file too, though lstat
// shows no hop into /proc (the kernel resolves /dev/fd and /proc/self on
// the way). The body goes through a copy of the descriptor: the file is
// neither replaced nor written over by what the process writes through the
// descriptor afterwards (a report sent to the same stdout).
TEST_F(IoDir, AtomicWriteThroughDevFdSharesTheDescriptorsPlace) {
  for (const std::string prefix : {"/dev/fd/", "/proc/self/fd/"}) {
    SCOPED_TRACE(prefix);
    const int fd = ::open(path("held.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    ASSERT_GE(fd, 0);
    ASSERT_EQ(::write(fd, "head ", 5), 5);
    struct stat before {};
    ASSERT_EQ(::fstat(fd, &before), 0);
    const std::string target = prefix + std::to_string(fd);
    const LinkEnd end = follow_links(target);
    EXPECT_TRUE(end.held);
    EXPECT_EQ(end.fd, fd);
    write_atomically(target, [](std::ostream& out) { out << "body"; });
    ASSERT_EQ(::write(fd, " tail", 5), 5);
    struct stat after {};
    ASSERT_EQ(::stat(path("held.txt").c_str(), &after), 0);
    ::close(fd);
    EXPECT_EQ(after.st_ino, before.st_ino) << "the held file was replaced";
    EXPECT_EQ(contents(path("held.txt")), "head body tail");
    EXPECT_EQ(files(), 1u);  // no temporary
  }
}

// A pipe this process holds with O_NONBLOCK (a parent may set it on our
// stdout) is opened afresh, blocking: a copy of the descriptor would share
// the flag and fail with EAGAIN once the pipe is full.
TEST(AtomicWrite, ANonBlockingPipeIsWrittenWhole) {
  int ends[2];
  ASSERT_EQ(::pipe(ends), 0);
  ASSERT_EQ(::fcntl(ends[1], F_SETFL, ::fcntl(ends[1], F_GETFL) | O_NONBLOCK), 0);
  const std::size_t size = 1 << 20;  // far past a pipe's buffer
  std::size_t got = 0;
  std::thread reader([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));  // let the pipe fill first
    char buf[1 << 16];
    for (ssize_t n; (n = ::read(ends[0], buf, sizeof buf)) > 0;) got += static_cast<std::size_t>(n);
  });
  EXPECT_NO_THROW(write_atomically("/proc/self/fd/" + std::to_string(ends[1]),
                                   [&](std::ostream& out) { out << std::string(size, 'x'); }));
  ::close(ends[1]);
  reader.join();
  ::close(ends[0]);
  EXPECT_EQ(got, size);
}

// Killed while the body is still writing: the temporary goes with the
// process, and the old file stays.
TEST_F(IoDir, AtomicWriteInterruptedBySignalLeavesNoTemporary) {
  write_atomically(path("t.txt"), [](std::ostream& out) { out << "old"; });
  // Ctrl-C and kill, and the quieter ends: a broken pipe, an abort, a timer,
  // I/O and user signals, a real-time one, a CPU or file-size limit.
  for (int sig : {SIGTERM, SIGINT, SIGPIPE, SIGABRT, SIGALRM, SIGIO, SIGUSR1, SIGRTMIN + 1, SIGXCPU, SIGXFSZ}) {
    SCOPED_TRACE(strsignal(sig));
    // A signal this process inherited as ignored (SIGINT in a background job
    // of a non-interactive shell, or under nohup) stays ignored by design
    // (the next test), so it cannot end the write here.
    struct sigaction now {};
    ::sigaction(sig, nullptr, &now);
    if (now.sa_handler == SIG_IGN) continue;
    EXPECT_EXIT(write_atomically(path("t.txt"),
                                 [sig](std::ostream& out) {
                                   out << std::string(1 << 20, 'x');  // part of it already in the file
                                   std::raise(sig);
                                 }),
                ::testing::KilledBySignal(sig), "");
    EXPECT_EQ(contents(path("t.txt")), "old");
    EXPECT_EQ(files(), 1u);
  }
}

// The clean-up handlers go only where the default action would end the
// process anyway. A signal the program ignores (SIGUSR2 here, as a pipeline
// ignores SIGPIPE) stays ignored; one whose default is to do nothing (a
// child ending, a terminal resize, ...) arriving mid-write must not remove
// the temporary, or the write fails at its rename. Run in a fresh process
// ("threadsafe" death test), as the handlers are installed once a process.
TEST_F(IoDir, CleanUpHandlersLeaveHarmlessAndIgnoredSignalsAlone) {
  const std::string style = GTEST_FLAG_GET(death_test_style);
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        std::signal(SIGUSR2, SIG_IGN);
        write_atomically(path("t.txt"), [](std::ostream& out) {
          out << std::string(1 << 17, 'x');  // the temporary exists on disk
          for (int sig : {SIGUSR2, SIGCHLD, SIGWINCH, SIGURG, SIGCONT}) std::raise(sig);
        });
        const bool written = contents(path("t.txt")) == std::string(1 << 17, 'x');
        fs::remove_all(dir_);  // the child's own directory: no TearDown after _Exit
        std::_Exit(written ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "");
  GTEST_FLAG_SET(death_test_style, style);
}

TEST_F(IoDir, WriteMeshFailureLeavesNoFile) {
  TetMesh mesh = testing::regular_tet();
  mesh.extras.blocks.push_back(PassThroughBlock{"prism", 6, {0, 1, 2, 3, 0, 1}, {}, {}, {}});
  EXPECT_THROW(write_mesh(mesh, path("p.vtu")), OutputError);
  EXPECT_EQ(files(), 0u);
}

// A directory opens as a stream on Linux and fails only at the first read;
// every reader says what it is instead of reporting a read error at line 1.
TEST_F(IoDir, DirectoryInputIsNamedAsSuch) {
  for (const char* name : {"d.vtk", "d.vtu", "d.msh", "d.mesh"}) {
    fs::create_directory(path(name));
    try {
      read_mesh(path(name));
      ADD_FAILURE() << name << ": no InputError";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(std::string(name) + ": is a directory, not a mesh file"), std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace tetsmooth
