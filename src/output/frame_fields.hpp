#pragma once
// Internal to the output layer: the fields of one field frame of NAME.h5 (docs/output-format.md, "/frames/NNNN"),
// computed from the solver state: the fields every frame has and those the /ANIM cards ask for
// (RunControl::anim). results_file.cpp writes them and describes them in NAME.xdmf.
#include <cstdint>
#include <string>
#include <vector>

#include "crumple/model/model.hpp"
#include "crumple/solver/solver_state.hpp"

namespace crumple {

// VTK's ghost-cell flag for a cell that is not shown (vtkDataSetAttributes::HIDDENCELL): ParaView leaves such
// cells out of what it draws, so a deleted element disappears from the animation.
inline constexpr std::uint8_t kHiddenCell = 32;

// The nodal field of every frame that holds the nodes' current positions: NAME.xdmf's geometry of the frame, not
// one of its attributes.
inline constexpr const char* kFrameCoordinates = "coordinates";

struct FrameField {
  std::string name;                 // dataset name, also the attribute name in ParaView
  int kind = -1;                    // the ElementKind of a cell field, -1 for a nodal field
  std::size_t width = 1;            // values per node or element
  bool is_bytes = false;           // uint8 flags in `bytes`, else float64 in `values`
  std::vector<double> values;       // row-major
  std::vector<std::uint8_t> bytes;
};

// Where the fields of a frame go, one at a time: a frame holds one field's buffers at once, not all of them (the
// frame is the run's peak of memory otherwise: about 200 bytes per shell).
class FieldSink {
 public:
  virtual ~FieldSink() = default;
  virtual void push_back(FrameField&& field) = 0;
};

// Every field of a frame of `state`, nodal fields first, then per element kind present (shell4, shell3, brick8)
// its cell fields, the kind's vtkGhostType last, each handed to `sink` as soon as it is made. Throws
// std::runtime_error when an array the frame needs does not fit the model (its message says which); the fields
// handed over before it are then the caller's to discard.
void frame_fields(const Model& model, const SolverState& state, FieldSink& sink);
// The same, collected.
std::vector<FrameField> frame_fields(const Model& model, const SolverState& state);

}  // namespace crumple
