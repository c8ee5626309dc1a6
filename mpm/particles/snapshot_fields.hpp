// The fields a particle snapshot can hold (`output.fields`, mpm/output/vtu_writer.cpp), derived
// from the two member tables: every Particles array with a snapshot name (kParticleArrays), every
// PointState member (kPointStateMembers: a tensor as 9 components, row by row, the symmetric
// stress as 6), and two derived from the stress (pressure, von_mises). A new member is a new
// field with no change here.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "mpm/particles/particles.hpp"

namespace impact::mpm {

struct SnapshotField {
  std::string name;
  std::string unit;  ///< SI; a 2D grid's mass and volume are per metre or per ring (docs/mpm.md)
  int components;
  /// Writes the field's `components` values of particle p (of P) to out.
  std::function<void(const Particles& P, std::size_t p, double* out)> values;
};

/// Every snapshot field, in the order the scene reader lists them.
const std::vector<SnapshotField>& snapshot_fields();

/// The field named `name`, or nullptr.
const SnapshotField* find_snapshot_field(const std::string& name);

}  // namespace impact::mpm
