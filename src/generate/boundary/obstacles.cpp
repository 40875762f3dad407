// Obstacles' set-up (obstacles.hpp): the grid over the polygon's box and the walls listed per cell,
// built once per run and checked against the memory limit. Out of line: it runs once.
#include "generate/boundary/obstacles.hpp"

#include <string>

namespace frontpack::detail {

std::size_t Obstacles::set_up(const std::vector<Wall>& walls, const RunFrame& frame, const SetupBudget& budget) {
  grid_ = CellGrid(0, 0, frame.width, frame.height, frame.rmax);
  probes_inside_ = frame.clearance < frame.rmax && !grid_.coarse;
  // The memory limit (FrontSettings::memory_limit) counts what is built here: the cell heads
  // (4 bytes a cell) and 12 bytes a block of cells; the (cell, wall) pairs, 16 bytes each while
  // they are listed (8, and as much again while the list moves or is copied grouped), then 12
  // (the grouped copy and the lists kept) with 1,028 bytes a walled block; then
  // FrontSettings::bytes_per_disk per disk. On a sliver 1e-7 high these lists, sized by the
  // grid's cells and not by the disks, were most of the run's memory (565 MB for 1.1M disks).
  const std::size_t need = grid_.cells() * sizeof(std::int32_t) + WallIndex::block_bytes(grid_);
  budget.check(need, "the grid over the polygon's box has " + std::to_string(grid_.cells()) + " cells");
  head_cell_.assign(grid_.cells(), kNoElement);

  // Walls per cell: those meeting the cell grown by rmax + the clearance (wall_index.cpp).
  const double reach = (frame.rmax + frame.clearance) * (1 + 1e-9) + 4 * frame.clearance;
  index_.build(walls, grid_, reach, need, budget);
  // What stays for the run; the disks have the rest of the limit.
  return head_cell_.size() * sizeof(std::uint32_t) + index_.bytes();
}

}  // namespace frontpack::detail
