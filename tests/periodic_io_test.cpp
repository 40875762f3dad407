// A periodic cell's outputs: the LAMMPS data file's box is the cell and its title names the
// boundary command, disks may cross a periodic side but their centres lie in the half-open cell;
// the VTP file carries the cell as field data and still reads back; the LAMMPS deck of a
// periodic cell has no wall disks and says `boundary p p p` or `p f p`; Yade's sets O.periodic
// (a shear cell with facet walls); LIGGGHTS's is the LAMMPS one's with primitive wall planes.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "frontpack/frontpack.hpp"
#include "test_support.hpp"

namespace fp = frontpack;

namespace {

// Disks crossing the left side and the bottom (a torus) or touching the walls (a shear cell).
const std::vector<fp::Disk> kCrossing = {{{0.25, 0.25}, 0.5}, {{9.75, 5}, 0.5}, {{5, 9.875}, 0.25}};
const std::vector<fp::Disk> kShear = {{{0.25, 0.5}, 0.5}, {{9.75, 5}, 0.5}, {{5, 9.75}, 0.25}};

std::string written(fp::Format format, const fp::Domain& domain, const std::vector<fp::Disk>& disks) {
  std::ostringstream out;
  fp::write(out, format, domain, disks);
  return out.str();
}

TEST(PeriodicIo, LammpsBoxIsTheCell) {
  const fp::Domain torus = fp::Domain::periodic(fp::Box{0, 0, 10, 10}, fp::Periodicity::xy);
  const std::string data = written(fp::Format::lammps, torus, kCrossing);
  EXPECT_NE(data.find("boundary p p p"), std::string::npos) << data;
  EXPECT_NE(data.find("\n0 10 xlo xhi\n0 10 ylo yhi\n"), std::string::npos) << data;
  const fp::Domain shear = fp::Domain::periodic(fp::Box{0, 0, 10, 10}, fp::Periodicity::x);
  const std::string shear_data = written(fp::Format::lammps, shear, kShear);
  EXPECT_NE(shear_data.find("boundary p f p"), std::string::npos) << shear_data;
  // The shear cell's walls are walls: a disk through the bottom is refused.
  EXPECT_THROW((void)written(fp::Format::lammps, shear, kCrossing), fp::OptionError);
  // A centre on the half-open side's far end belongs to the next cell.
  EXPECT_THROW((void)written(fp::Format::lammps, torus, {{{10, 5}, 0.5}}), fp::OptionError);
  // A walled square with the same disks refuses them: they cross its edges.
  EXPECT_THROW((void)written(fp::Format::lammps, fp::Domain::from_wkt("POLYGON((0 0,10 0,10 10,0 10,0 0))"), kCrossing),
               fp::OptionError);
}

TEST(PeriodicIo, VtpCarriesTheCellAndReadsBack) {
  fp::test::ScratchDir dir;
  const fp::Domain torus = fp::Domain::periodic(fp::Box{-1, 0.5, 9, 10.5}, fp::Periodicity::xy);
  const std::string vtp = written(fp::Format::vtp, torus, kCrossing);
  EXPECT_NE(vtp.find("Name=\"periodic_cell\""), std::string::npos);
  EXPECT_NE(vtp.find("-1 0.5 9 10.5"), std::string::npos);
  EXPECT_NE(vtp.find("Name=\"periodic_axes\""), std::string::npos);
  const auto path = dir.path() / "p.vtp";
  fp::write_file(path, fp::Format::vtp, torus, kCrossing);
  const std::vector<fp::Disk> back = fp::read_disks(path, fp::DiskFormat::vtp);
  ASSERT_EQ(back.size(), kCrossing.size());
  for (std::size_t i = 0; i < back.size(); ++i) {
    EXPECT_EQ(back[i].centre, kCrossing[i].centre);
    EXPECT_EQ(back[i].radius, kCrossing[i].radius);
  }
  // A polygonal domain: no field data.
  EXPECT_EQ(
      written(fp::Format::vtp, fp::Domain::from_wkt("POLYGON((0 0,10 0,10 10,0 10,0 0))"), kCrossing).find("FieldData"),
      std::string::npos);
}

TEST(PeriodicIo, LammpsDeckOfAPeriodicCell) {
  fp::DeckOptions options;
  options.densities = {2500};
  const fp::Domain torus = fp::Domain::periodic(fp::Box{0, 0, 10, 10}, fp::Periodicity::xy);
  const std::vector<fp::DeckFile> files = fp::make_deck(torus, kCrossing, {}, options);
  ASSERT_GE(files.size(), 2u);
  EXPECT_EQ(files[0].name, "deck.data");
  EXPECT_NE(files[0].text.find("3 atoms\n1 atom types"), std::string::npos) << files[0].text;  // no wall disks
  EXPECT_NE(files[1].text.find("boundary p p p\n"), std::string::npos);
  EXPECT_EQ(files[1].text.find("wall/gran"), std::string::npos);    // neither wall planes
  EXPECT_EQ(files[1].text.find("freeze"), std::string::npos);       // nor frozen wall disks
  EXPECT_EQ(files[1].text.find("fix gravity"), std::string::npos);  // nothing holds a torus up
  const fp::Domain shear = fp::Domain::periodic(fp::Box{0, 0, 10, 10}, fp::Periodicity::x);
  const std::vector<fp::DeckFile> shear_files = fp::make_deck(shear, kShear, {}, options);
  EXPECT_NE(shear_files[0].text.find("3 atoms\n1 atom types"), std::string::npos);
  EXPECT_NE(shear_files[1].text.find("boundary p f p\n"), std::string::npos);
  EXPECT_NE(shear_files[1].text.find("wall/gran hooke/history"), std::string::npos);
  EXPECT_NE(shear_files[1].text.find(" yplane 0 10\n"), std::string::npos);
  EXPECT_NE(shear_files[1].text.find("fix gravity free gravity 9.81 vector 0 -1 0\n"), std::string::npos);
  options.simulator = fp::Simulator::liggghts;
  const std::vector<fp::DeckFile> liggghts = fp::make_deck(torus, kCrossing, {}, options);
  ASSERT_EQ(liggghts.size(), 3u);  // deck.data, in.frontpack, domain.wkt: no mesh
  EXPECT_NE(liggghts[1].text.find("boundary p p p\n"), std::string::npos);
  EXPECT_EQ(liggghts[1].text.find("wall/gran"), std::string::npos);
  EXPECT_EQ(liggghts[1].text.find("fix gravity"), std::string::npos);
  const std::string liggghts_shear = fp::make_deck(shear, kShear, {}, options)[1].text;
  EXPECT_NE(liggghts_shear.find("boundary p f p\n"), std::string::npos);
  EXPECT_NE(liggghts_shear.find("primitive type 2 yplane 0\n"), std::string::npos);
  EXPECT_NE(liggghts_shear.find("primitive type 2 yplane 10\n"), std::string::npos);
  EXPECT_NE(liggghts_shear.find("fix gravity all gravity 9.81 vector 0 -1 0\n"), std::string::npos);
}

TEST(PeriodicIo, YadeDeckOfAPeriodicCell) {
  fp::DeckOptions options;
  options.simulator = fp::Simulator::yade;
  options.densities = {2500};
  const fp::Domain torus = fp::Domain::periodic(fp::Box{0, 0, 10, 10}, fp::Periodicity::xy);
  const std::string torus_script = fp::make_deck(torus, kCrossing, {}, options)[1].text;
  EXPECT_NE(torus_script.find("O.periodic = True\nO.cell.setBox(LX, LY, 5 * HALF_HEIGHT)\n"), std::string::npos);
  EXPECT_NE(torus_script.find("CELL = (0, 0, 10, 10)"), std::string::npos);
  EXPECT_NE(torus_script.find("RINGS = []\n"), std::string::npos);  // no wall facets
  EXPECT_EQ(torus_script.find("WALLS"), std::string::npos);
  EXPECT_NE(torus_script.find("NewtonIntegrator(damping=0.3, gravity=(0, 0, 0))"), std::string::npos);
  const fp::Domain shear = fp::Domain::periodic(fp::Box{0, 0, 10, 10}, fp::Periodicity::x);
  const std::string shear_script = fp::make_deck(shear, kShear, {}, options)[1].text;
  EXPECT_NE(shear_script.find("for (ax, ay), (bx, by) in WALLS:"), std::string::npos);
  EXPECT_NE(shear_script.find("LY = CELL[3] - CELL[1] + 2 * HALF_HEIGHT"), std::string::npos);
  EXPECT_NE(shear_script.find("NewtonIntegrator(damping=0.3, gravity=(0, -9.81, 0))"), std::string::npos);
}

}  // namespace
