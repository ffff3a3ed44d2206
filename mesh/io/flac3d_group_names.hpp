#pragma once
// The names a FLAC3D grid's regions go by in other formats (Gmsh's physical
// names): the groups that hold the region's zones, one a slot, written
// "group" in the default slot and "slot=group" in others (FLAC3D's own way
// of naming a group in a slot), joined by " + ": "Soil + stage 1=excavated".
// A group or slot that holds "=", " + " or a quote, or is empty, is quoted
// ('E=200', or "it's" in double quotes). A new grid reads such a name back
// into its groups (flac3d_io.hpp; not a public API); a name of another tool
// that reads as such (Gmsh's "phi=30") becomes the groups it spells.
#include <string>
#include <string_view>
#include <vector>

namespace tetsmooth::flac3d {

// A group, and the slot that holds it ("Default" for the default slot).
struct Membership {
  std::string slot, group;
};

// Whether a slot is the default one: "Default" (in any case), no slot at
// all, or "1" (older grids, and meshio, number the slots).
bool is_default_slot(std::string_view slot);

// The name of a region held by these groups, each in its own slot.
std::string region_name(const std::vector<Membership>& groups);

// The groups a name gives: its parts, where it reads as groups of different
// slots, else the whole name as one group of the default slot.
std::vector<Membership> memberships_of(const std::string& name);

}  // namespace tetsmooth::flac3d
