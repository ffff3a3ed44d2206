#include "apps/cli_help.hpp"

#include "generators/models.hpp"

#ifndef TETSMOOTH_VERSION
#error "TETSMOOTH_VERSION is set by apps/CMakeLists.txt from the project version"
#endif

namespace tetsmooth::cli {
namespace {

const char* const kExitCodes = R"(Exit status:
  0  success
  1  internal error (a bug, or out of memory)
  2  usage error: unknown command or option, bad value, unknown file extension
     or model name
  3  bad input: unreadable or malformed mesh file, invalid mesh
     (node index out of range, non-finite coordinate, no tets, 4- and
     10-node tets mixed, a midside node that is a corner or on two edges)
  4  output error: an output file or report cannot be written
     (no partial file is ever left behind)
  5  device error: --device cuda without a usable GPU, CUDA support not built,
     or a mesh that does not fit in the GPU's memory
)";

const char* const kFormats = R"(Formats (chosen from the file name; --format/--output-format override):
  .node/.ele  tetgen        TetGen node + element files (give either name, or the base name)
  .vtu        vtu           VTK XML UnstructuredGrid
  .vtk        vtk           legacy VTK, ASCII (reading also takes BINARY)
  .msh        msh41         Gmsh 4.1 ASCII (reading detects 2.2 or 4.1, ASCII or binary)
              msh41-binary  Gmsh 4.1 binary
              msh22         Gmsh 2.2 ASCII
  .mesh       medit         Medit ASCII
  .inp        abaqus        Abaqus/CalculiX input deck, flat or with parts and an
                            assembly (a deck read is written back whole, with the
                            new coordinates; parts' nodes in part coordinates)
  .bdf/.nas   nastran       Nastran bulk data, small, large or free field (a deck
                            read is written back whole, moved GRIDs in large field)
  .f3grid     flac3d        FLAC3D grid, text or binary (.flac3d too; a grid read is
                            written back whole, with the new coordinates; zone groups
                            are regions)
  .exo/.e     exodus        Exodus II (.ex2, .g and .gen too; a file read is written
                            back whole, with the new coordinates; element blocks are
                            regions, node and side sets pinned)
  .cdb        ansys         ANSYS Mechanical APDL archive (CDWRITE; a file read is
                            written back whole, moved NBLOCK records rewritten;
                            materials are regions, node components pinned)
  .k/.key     lsdyna        LS-DYNA keyword deck (.dyn too; a deck read is written
                            back whole, moved *NODE cards rewritten; parts are
                            regions, node sets and constrained nodes pinned)
  .tsm        tsm           tetsmooth binary cache
)";

std::string model_list() {
  std::string list;
  for (const std::string& name : paper_model_names()) list += (list.empty() ? "" : ", ") + name;
  return list;
}

std::string top_level() {
  return std::string(R"(tetsmooth - adaptive Laplacian smoothing of tetrahedral meshes, on the GPU or CPU

Usage:
  tetsmooth generate MODEL -o OUT [--seed N]       build a test mesh
  tetsmooth smooth IN -o OUT [options]             improve a mesh, report quality before/after
  tetsmooth quality IN [--json] [--worst K]        quality statistics and the worst tets
  tetsmooth convert IN OUT                         change the file format
  tetsmooth help COMMAND | COMMAND --help          options of one command
  tetsmooth --version

Only interior nodes move; boundary nodes and nodes the file pins stay put, so
the geometry and the boundary surface are unchanged. Quality is the radius
ratio q = 3 r_in / R: 1 for the regular tet, near 0 for a sliver, negative for
an inverted tet. Reports and messages go to stderr; `quality` writes to stdout.

)") + kFormats +
         "\n" + kExitCodes;
}

std::string generate_help() {
  return "Usage: tetsmooth generate MODEL -o OUT [--seed N] [--output-format F] [-q]\n\n"
         "Builds a test mesh and writes it to OUT.\n\n"
         "MODEL is one of the paper's models (" +
         model_list() +
         ", meshed by TetGen)\nor lattice-N: N^3 jittered cubes of 6 tets each, (N+1)^3 nodes.\n\n"
         "Options:\n"
         "  -o, --output OUT       where to write the mesh (format from the extension)\n"
         "  --seed N               random seed; the same seed gives the same mesh (default 1;\n"
         "                         slope-77k is fixed and ignores it)\n"
         "  --output-format F      write format F whatever OUT's extension\n"
         "  -q, --quiet            print nothing but errors\n\n" +
         kExitCodes;
}

std::string smooth_help() {
  return std::string(R"(Usage: tetsmooth smooth IN -o OUT [options]

Moves every interior node towards the centroid of its neighbours. The adaptive
method keeps a move only if it raises the worst quality of the node's tets, so
it never makes the mesh worse (except CUDA's multiblock and singleblock in form
B, the paper's racy variants, which read neighbours while they move and can
invert a few tets); the ordinary method always moves and can invert tets in
concave regions. Prints the quality before and after on stderr.

Second-order (10-node) tets: the corners move, and each midside node moves
with its edge's corners, keeping its offset from the edge's midpoint; a tet
with a curved edge keeps its shape (its corners stay put).

Options:
  -o, --output OUT          where to write the smoothed mesh (required); it may be IN,
                            which is replaced only once the whole result is written
  --method adaptive|ordinary   (default adaptive)
  --form A|B                A: every node from the previous sweep's positions (Jacobi);
                            B: in place, later nodes see earlier moves (default B, converges faster)
  --device auto|cpu|cuda    auto picks CUDA when a GPU is usable, else the CPU (default auto)
  --threads N               CPU threads, 0 = all cores (default 0). --threads 1 is the serial
                            reference in natural node order; other counts visit nodes colour by
                            colour, so the result does not depend on the thread count. They
                            build the topology too (on the host, for CUDA)
  --strategy coloured|multiblock|singleblock
                            CUDA: how sweeps are launched (default coloured in form B,
                            multiblock in form A; coloured is a form B scheme)
  --layout aos|soa          CUDA: coordinates as xyz triples or three arrays (default aos)
  --precision float|double  CUDA: arithmetic of the smoother; the CPU always uses double
                            (default double)
  --max-iter N              at most N sweeps (default 100)
  --tol X                   stop when no node moves farther than X times the mean edge
                            length in a sweep (default 1e-4)
  --report FILE.json        write options, per-sweep counts, timings and quality before/after
                            (- for standard output)
  --progress auto|always|never
                            a progress line (sweep, moves, current min and mean quality):
                            auto redraws one on a terminal only; always also writes one to
                            a log, 10 s apart or more; never shows none (default auto)
  --format F                read IN as format F
  --output-format F         write OUT as format F
  -q, --quiet               print nothing but errors

VTU, VTK and MSH outputs carry a per-tet field "quality" (radius ratio) and a
per-node field "boundary" (1 on the boundary surface) for ParaView or Gmsh.

)") + kFormats +
         "\n" + kExitCodes;
}

std::string quality_help() {
  return std::string(R"(Usage: tetsmooth quality IN [--json] [--worst K] [--format F] [-q]

Prints the radius ratio q (min/mean/max, a 10-bin histogram), the number of
tets with q < 0.1, inverted and degenerate tets, the smallest dihedral angle,
the mean of the mean-ratio metric, and the K worst tets with their nodes.
Tet and node indices are 0-based, in file order, whatever the file numbers;
where the file numbers its elements or nodes itself (Gmsh tags, Abaqus
numbers, Nastran ids, FLAC3D ids), each number naming one, its numbers
follow them (not for Abaqus parts that number theirs alike).
Second-order (10-node) tets are measured by their corner tets.

Options:
  --json            print JSON instead of text (to stdout)
  --worst K         list the K worst tets (default 10, 0 for none)
  --format F        read IN as format F
  -q, --quiet       no warnings on stderr

)") + kExitCodes;
}

std::string convert_help() {
  return std::string(R"(Usage: tetsmooth convert IN OUT [--format F] [--output-format F] [-q]

Reads IN and writes it to OUT in the format OUT's extension names. Node
coordinates and tets are kept exactly; what else survives depends on the
target format (see the README's table of formats).

Options:
  --format F          read IN as format F
  --output-format F   write OUT as format F
  -q, --quiet         print nothing but errors

)") + kFormats +
         "\n" + kExitCodes;
}

}  // namespace

std::string help_text(const std::string& command) {
  if (command == "generate") return generate_help();
  if (command == "smooth") return smooth_help();
  if (command == "quality") return quality_help();
  if (command == "convert") return convert_help();
  return top_level();
}

std::string version_text() {
#ifdef TETSMOOTH_HAVE_CUDA
  const char* cuda = "built";
#else
  const char* cuda = "not built";
#endif
  return std::string("tetsmooth ") + TETSMOOTH_VERSION + " (CUDA backend " + cuda + ")\n";
}

}  // namespace tetsmooth::cli
