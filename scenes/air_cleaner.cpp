// Scene "air-cleaner": an air-cleaner subassembly (housing, filter canister, hoses) inside a
// frame welded from round tubes (paper §V, TC Air Cleaner Subassembly).
#include "swept/scenes/modeling.h"
#include "swept/scenes/scene_model.h"

namespace swept::scenes::detail {

namespace {

// The subassembly in its own frame: origin at the centre of the housing's footprint, z up,
// housing bottom at z = 0. Envelope ≈ x [-186, 280], y [-178, 122], z [0, 346].
TopoDS_Shape air_cleaner_body() {
  std::vector<TopoDS_Shape> parts;
  // Housing: a box with every edge rounded.
  parts.push_back(rounded_box({-180, -110, 0}, {180, 110, 160}, 20));
  // Lid: a chamfered plate with eight bolt holes.
  {
    TopoDS_Shape lid = chamfered_box({-186, -116, 160}, {186, 116, 176}, 4);
    std::vector<TopoDS_Shape> holes;
    for (double x : {-165.0, -55.0, 55.0, 165.0})
      for (double y : {-98.0, 98.0}) holes.push_back(cylinder({x, y, 150}, {0, 0, 1}, 5, 40));
    parts.push_back(cut(lid, holes));
  }
  // Filter canister: a cylinder with a rounded top edge and a turned cap.
  {
    TopoDS_Shape can = cylinder({-80, 0, 176}, {0, 0, 1}, 70, 150);
    can = fillet_edges_in(can, {-151, -71, 325.5}, {-9, 71, 326.5}, 12);
    parts.push_back(can);
    parts.push_back(revolved({{0, 0, 0}, {40, 0, 0}, {40, 0, 8}, {26, 0, 20}, {0, 0, 20}}, {-80, 0, 326}));
  }
  // Outlet hose: bent hollow tube from the housing's side, up and back over the lid.
  parts.push_back(bent_tube({{170, 0, 80}, {250, 0, 80}, {250, 0, 250}, {120, 0, 290}}, 55, 30, 25));
  // Inlet hose: from the canister, forward, across the front and down.
  parts.push_back(bent_tube({{-80, -60, 250}, {-80, -150, 250}, {60, -150, 250}, {60, -150, 60}}, 50, 28, 23));
  // Corrugated snorkel on the lid (a turned bellows).
  {
    std::vector<Vec3> profile{{0, 0, 0}};
    for (int i = 0; i <= 12; ++i) profile.push_back({i % 2 == 0 ? 24.0 : 30.0, 0, 8.0 * i});
    profile.push_back({0, 0, 96});
    parts.push_back(revolved(profile, {80, 55, 176}));
  }
  // Mounting brackets: chamfered plates with two holes each, on the back face.
  for (double x0 : {-150.0, 90.0}) {
    TopoDS_Shape plate = chamfered_box({x0, 110, 20}, {x0 + 60, 122, 140}, 2);
    plate = cut(plate, {cylinder({x0 + 30, 100, 50}, {0, 1, 0}, 7, 30), cylinder({x0 + 30, 100, 110}, {0, 1, 0}, 7, 30)});
    parts.push_back(plate);
  }
  return compound(parts);
}

// The welded frame, in the world: tube centre lines on the box x ±330, y ±260, z 0…600.
// Top: two cross bars (openings 180 mm wide, narrower than the subassembly in any
// orientation); sides and back: rails at 200 and 390 mm; front: one low rail at 150 mm, above
// which the only opening big enough for the subassembly is.
TopoDS_Shape frame() {
  const double ro = 20, ri = 0, bend = 50;  // tubes modelled closed: their bore is invisible from outside
  const double X = 330, Y = 260, Z = 600;
  std::vector<TopoDS_Shape> tubes;
  for (double z : {0.0, Z}) tubes.push_back(bent_tube({{-X, -Y, z}, {X, -Y, z}, {X, Y, z}, {-X, Y, z}}, bend, ro, ri, true));
  for (double x : {-X + 15, X - 15})
    for (double y : {-Y + 15, Y - 15}) tubes.push_back(tube({x, y, -10}, {x, y, Z + 10}, ro, ri));
  for (double z : {200.0, 390.0}) {
    tubes.push_back(tube({-X, Y, z}, {X, Y, z}, ro, ri));  // back
    for (double x : {-X, X}) tubes.push_back(tube({x, -Y, z}, {x, Y, z}, ro, ri));  // sides
  }
  tubes.push_back(tube({-X, -Y, 150}, {X, -Y, 150}, ro, ri));   // front, low
  tubes.push_back(tube({-X, Y, 0}, {X, Y, Z}, ro * 0.8, ri * 0.8));  // back diagonal brace
  for (double x : {-110.0, 110.0}) tubes.push_back(tube({x, -Y, Z}, {x, Y, Z}, ro, ri));  // top
  for (double y : {-90.0, 90.0}) tubes.push_back(tube({-X, y, 0}, {X, y, 0}, ro, ri));    // bottom
  TopoDS_Shape welded = fuse(tubes);
  // Feet: chamfered plates with a bolt hole under the four corners.
  std::vector<TopoDS_Shape> all{welded};
  for (double x : {-X + 15, X - 15})
    for (double y : {-Y + 15, Y - 15}) {
      TopoDS_Shape foot = chamfered_box({x - 45, y - 45, -26}, {x + 45, y + 45, -10}, 3);
      all.push_back(cut(foot, {cylinder({x + (x < 0 ? -28 : 28), y + (y < 0 ? -28 : 28), -40}, {0, 0, 1}, 8, 40)}));
    }
  return compound(all);
}

}  // namespace

SceneModel build_air_cleaner() {
  SceneModel m;
  m.parts.push_back({"air_cleaner.stl", true, air_cleaner_body()});
  m.parts.push_back({"frame.stl", false, frame()});
  // Centred in the frame, 10 mm above the bottom cross bars (their top is at z = 20).
  m.start = Pose::from_translation({-47, 28, 30});
  m.goal_outside = true;
  m.goal_margin = 20;
  m.bounds_min = {-900, -900, -500};
  m.bounds_max = {900, 900, 1200};
  m.clearance = 1.0;
  m.test_deflection = {0.130753, 3.22096};
  m.paper_deflection = {0.00144633, 0.00782917};
  m.comment =
      "air-cleaner: an air-cleaner subassembly (housing, filter canister, bent hoses) inside a\n"
      "frame welded from round tubes; it must leave the frame. The top and three sides are\n"
      "barred; the front opening lies above a low rail: lift, then move out forwards (-y).";
  return m;
}

}  // namespace swept::scenes::detail
