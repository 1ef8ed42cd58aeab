// Scene "cylinder-head": a cylinder head lifted just above a cylinder block, inside a frame of
// round tubes (paper §V, TC Cylinder Head).
#include "swept/scenes/modeling.h"
#include "swept/scenes/scene_model.h"

#include <cmath>

namespace swept::scenes::detail {

namespace {

constexpr double kBores[4] = {-165, -55, 55, 165};
constexpr double kBoltX[5] = {-220, -110, 0, 110, 220};

// The head in its own frame: gasket face at z = 0, centred on the bores.
// Envelope ≈ x [-240, 240], y [-178, 160], z [-68, 175].
TopoDS_Shape head() {
  std::vector<TopoDS_Shape> parts;
  TopoDS_Shape casting = chamfered_box({-240, -105, 0}, {240, 105, 110}, 3);
  std::vector<TopoDS_Shape> tools;
  for (double x : kBores) {
    tools.push_back(sphere({x, 0, -20}, 45));                           // combustion chamber
    tools.push_back(cylinder({x, -120, 45}, {0, 1, 0}, 16, 70));        // intake port
    tools.push_back(cylinder({x, 50, 45}, {0, 1, 0}, 15, 70));          // exhaust port
    tools.push_back(cylinder({x, 0, 50}, {0, 0, 1}, 8, 80));            // spark plug bore
  }
  for (double x : kBoltX)
    for (double y : {-80.0, 80.0}) tools.push_back(cylinder({x, y, -10}, {0, 0, 1}, 7, 200));  // head bolts
  parts.push_back(cut(casting, tools));
  // Cooling fins on the top deck.
  for (int i = 0; i < 16; ++i) {
    const double x = -227.0 + 30.0 * i;
    parts.push_back(chamfered_box({x, -95, 110}, {x + 4, 95, 150}, 1.2));
  }
  parts.push_back(rounded_box({-230, -60, 148}, {230, 60, 175}, 10));  // cam cover
  // Intake runners out of the -y face, down to a plenum beside the block.
  for (double x : kBores) parts.push_back(bent_tube({{x, -100, 45}, {x, -150, 45}, {x, -150, -40}}, 30, 16, 13));
  parts.push_back(tube({-215, -150, -40}, {215, -150, -40}, 28, 24));
  for (double x : {-215.0, 215.0}) parts.push_back(cylinder({x, -150, -40}, {x < 0 ? -1.0 : 1.0, 0, 0}, 28, 6));
  // Exhaust stubs on the +y face, with flanges.
  for (double x : kBores) {
    parts.push_back(tube({x, 100, 45}, {x, 160, 45}, 18, 14));
    parts.push_back(chamfered_box({x - 28, 104, 17}, {x + 28, 112, 73}, 1.5));
  }
  return compound(parts);
}

// The block (world): bottom at z = 120, gasket deck at z = 420, oil pan below.
TopoDS_Shape block() {
  TopoDS_Shape b = rounded_box({-250, -110, 120}, {250, 110, 420}, 10);
  std::vector<TopoDS_Shape> tools;
  for (double x : kBores) tools.push_back(cylinder({x, 0, 220}, {0, 0, 1}, 42, 210));  // bores
  for (double x : kBoltX)
    for (double y : {-80.0, 80.0}) tools.push_back(cylinder({x, y, 270}, {0, 0, 1}, 6, 160));
  for (double x : {-110.0, 0.0, 110.0})
    for (double y : {-58.0, 58.0}) tools.push_back(cylinder({x, y, 380}, {0, 0, 1}, 4, 50));  // coolant
  b = cut(b, tools);
  TopoDS_Shape pan = rounded_box({-230, -100, 0}, {230, 100, 125}, 15);
  return compound({b, pan});
}

// Frame (world): tubes on x ±360, y ±280, z 0…950. Rails at 250, 450, 650, 850 on all four
// sides leave gaps lower than the head; one top cross bar at y = +60 leaves a 300 mm slot,
// narrower than the head lying flat (338 mm) but wider than the head on its side.
TopoDS_Shape frame() {
  const double ro = 20, ri = 0;  // tubes modelled closed: their bore is invisible from outside
  const double X = 360, Y = 280, Z = 950;
  std::vector<TopoDS_Shape> tubes;
  for (double z : {0.0, Z}) tubes.push_back(bent_tube({{-X, -Y, z}, {X, -Y, z}, {X, Y, z}, {-X, Y, z}}, 60, ro, ri, true));
  const double inset = 60.0 * (1.0 - std::sqrt(0.5));
  for (double x : {-X + inset, X - inset})
    for (double y : {-Y + inset, Y - inset}) tubes.push_back(tube({x, y, -10}, {x, y, Z + 10}, ro, ri));
  for (double z : {250.0, 450.0, 650.0, 850.0}) {
    for (double y : {-Y, Y}) tubes.push_back(tube({-X, y, z}, {X, y, z}, ro, ri));
    for (double x : {-X, X}) tubes.push_back(tube({x, -Y, z}, {x, Y, z}, ro, ri));
  }
  tubes.push_back(tube({-X, 60, Z}, {X, 60, Z}, ro, ri));
  return fuse(tubes);
}

}  // namespace

SceneModel build_cylinder_head() {
  SceneModel m;
  m.parts.push_back({"cylinder_head.stl", true, head()});
  m.parts.push_back({"cylinder_block.stl", false, block()});
  m.parts.push_back({"frame.stl", false, frame()});
  // Lifted 15 mm off the deck; the plenum hangs beside the block (12 mm away).
  m.start = Pose::from_translation({0, 0, 435});
  m.goal_outside = true;
  m.goal_margin = 20;
  m.bounds_min = {-1000, -1000, -200};
  m.bounds_max = {1000, 1000, 1800};
  m.clearance = 1.0;
  m.test_deflection = {0.805624, 0.402317};
  m.paper_deflection = {0.00621612, 0.00803184};
  m.comment =
      "cylinder-head: a cylinder head lifted 15 mm off its block, inside a tube frame; it must\n"
      "leave the frame. The top slot is narrower than the head lying flat: lift, tilt it on\n"
      "its side, move over the slot, lift out.";
  return m;
}

}  // namespace swept::scenes::detail
