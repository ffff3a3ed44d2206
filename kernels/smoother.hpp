#pragma once
// Entry points of the smoothers. Each updates mesh.xyz in place and returns
// what it did. Boundary nodes, nodes the file pins (mesh.fixed) and nodes in
// no tet never move.
#include <string>

#include "kernels/smooth_options.hpp"
#include "mesh/colouring.hpp"
#include "mesh/tet_mesh.hpp"

namespace tetsmooth {

// The CPU smoother: options.threads == 1 is the serial reference; more
// threads run Form A over nodes in parallel and Form B colour by colour.
// `colouring` overrides the computed one (for tests against the GPU).
SmoothResult smooth_cpu(TetMesh& mesh, const SmoothOptions& options, const Colouring* colouring = nullptr);

// The CUDA smoother. Throws DeviceError when CUDA support is not built or no
// device is usable, and InputError for a mesh validate_mesh refuses (no
// tets, an index out of range, arrays of the wrong length).
SmoothResult smooth_cuda(TetMesh& mesh, const SmoothOptions& options, const Colouring* colouring = nullptr);

// True when a CUDA device can be used; otherwise `why` says why not.
bool cuda_available(std::string* why = nullptr);

// Picks the backend: Auto means CUDA when available, else CPU. Of the entry
// points, only this one smooths second-order meshes (TetMesh::midsides), through
// smooth_second_order (kernels/second_order_smoothing.hpp): curved tets keep
// their corners, midside nodes move with their edges, and no tet may fold.
// smooth_cpu and smooth_cuda move the corners alone, and leave midside nodes
// where they are.
SmoothResult smooth(TetMesh& mesh, const SmoothOptions& options, Device device);

}  // namespace tetsmooth
