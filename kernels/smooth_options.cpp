#include "kernels/smooth_options.hpp"

namespace tetsmooth {

const char* to_string(Method m) { return m == Method::Adaptive ? "adaptive" : "ordinary"; }
const char* to_string(Form f) { return f == Form::A ? "A" : "B"; }
const char* to_string(Layout l) { return l == Layout::AoS ? "AoS" : "SoA"; }
const char* to_string(Strategy s) {
  switch (s) {
    case Strategy::SingleBlock: return "SingleBlock";
    case Strategy::MultiBlock: return "MultiBlock";
    case Strategy::Coloured: return "Coloured";
  }
  return "?";
}
const char* to_string(Precision p) { return p == Precision::Float ? "float" : "double"; }
const char* to_string(StopReason r) {
  switch (r) {
    case StopReason::NoMoves: return "no-moves";
    case StopReason::Tolerance: return "tolerance";
    case StopReason::MaxIterations: return "max-iterations";
    case StopReason::NotStarted: return "not-started";
  }
  return "?";
}

}  // namespace tetsmooth
