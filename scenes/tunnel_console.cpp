// Scene "tunnel-console": a car's centre console taken out of the cabin between the dashboard,
// the gear selector, the hand brake, the seats and the roof (paper §V, TC Tunnel Console,
// Fig. 2 and 3). World: x forward, y left, z up, floor at z = 0.
#include "swept/scenes/modeling.h"
#include "swept/scenes/scene_model.h"

#include <cmath>
#include <numbers>

namespace swept::scenes::detail {

namespace {

// The console in its own frame: footprint centred at the origin, bottom at z = 0.
// A hollow moulded cover (4 mm wall, open below) with a gear-selector hole, a hand-brake slot,
// two cup holders, an armrest and switch buttons. Envelope: x [-300, 300], y [-110, 110], z [0, 330].
TopoDS_Shape console() {
  std::vector<TopoDS_Shape> parts;
  TopoDS_Shape shell = rounded_box({-300, -110, 0}, {300, 110, 250}, 30);
  std::vector<TopoDS_Shape> tools{rounded_box({-296, -106, -30}, {296, 106, 246}, 26)};
  tools.push_back(cylinder({150, 0, 200}, {0, 0, 1}, 44, 100));  // gear selector
  tools.push_back(box({-128, -22, 200}, {-12, 22, 300}));         // hand-brake slot
  for (double x : {-128.0, -12.0}) tools.push_back(cylinder({x, 0, 200}, {0, 0, 1}, 22, 100));
  for (double y : {-50.0, 50.0}) tools.push_back(cylinder({70, y, 200}, {0, 0, 1}, 42, 100));  // cup holders
  parts.push_back(cut(shell, tools));
  for (double y : {-50.0, 50.0}) {
    parts.push_back(tube({70, y, 190}, {70, y, 250}, 42, 39));
    parts.push_back(cylinder({70, y, 187}, {0, 0, 1}, 42, 3));
  }
  parts.push_back(rounded_box({-300, -110, 250}, {-165, 110, 330}, 20));  // armrest
  parts.push_back(cylinder({-165, -100, 300}, {0, 1, 0}, 8, 200));       // armrest hinge
  for (int i = 0; i < 6; ++i) {                                            // switch buttons
    const double x = 210.0 + 28.0 * (i % 3), y = i < 3 ? -30.0 : 10.0;
    parts.push_back(rounded_box({x, y, 248}, {x + 20, y + 20, 256}, 3));
  }
  return compound(parts);
}

// A door opening (rounded rectangle, corner radius r) cut through a side wall at y ∈ [y0, y1].
std::vector<TopoDS_Shape> door_tools(double y0, double y1, double x0, double x1, double z0, double z1, double r) {
  const double ya = y0 - 10, yb = y1 + 10;
  std::vector<TopoDS_Shape> tools{box({x0 + r, ya, z0}, {x1 - r, yb, z1}), box({x0, ya, z0 + r}, {x1, yb, z1 - r})};
  for (double x : {x0 + r, x1 - r})
    for (double z : {z0 + r, z1 - r}) tools.push_back(cylinder({x, ya, z}, {0, 1, 0}, r, yb - ya));
  return tools;
}

// Floor, transmission tunnel and the two side walls with door openings.
TopoDS_Shape body_in_white() {
  std::vector<TopoDS_Shape> parts;
  parts.push_back(box({-900, -720, -20}, {900, 720, 0}));
  parts.push_back(rounded_box({-900, -140, -10}, {900, 140, 250}, 30));
  for (double side : {-1.0, 1.0}) {
    const double y0 = side > 0 ? 700 : -720, y1 = y0 + 20;
    parts.push_back(cut(box({-900, y0, 0}, {900, y1, 1150}), door_tools(y0, y1, -450, 550, 300, 1050, 90)));
  }
  return compound(parts);
}

TopoDS_Shape roof() { return rounded_box({-900, -720, 1150}, {900, 720, 1175}, 8); }

TopoDS_Shape dashboard() {
  std::vector<TopoDS_Shape> parts;
  parts.push_back(rounded_box({310, -700, 520}, {760, 700, 850}, 40));
  parts.push_back(chamfered_box({290, -200, 515}, {330, 200, 535}, 3));  // lip over the console's nose
  // Steering column and wheel (driver on the left, +y).
  const Vec3 axis = Vec3(-1, 0, 0.35).normalized();
  const Vec3 hub(330, 400, 820);
  parts.push_back(cylinder(hub - 240 * axis, axis, 30, 240));
  const Vec3 e1(0, 1, 0), e2 = axis.cross(e1).normalized();
  const double R = 180;
  parts.push_back(bent_tube({hub + R * (e1 + e2), hub + R * (-e1 + e2), hub + R * (-e1 - e2), hub + R * (e1 - e2)}, R, 15, 0, true));
  for (double a : {0.0, 2.0 * std::numbers::pi / 3.0, 4.0 * std::numbers::pi / 3.0})
    parts.push_back(tube(hub, hub + (R - 5) * (std::cos(a) * e1 + std::sin(a) * e2), 10, 0));  // spokes
  return compound(parts);
}

TopoDS_Shape gear_selector() {
  std::vector<TopoDS_Shape> parts;
  parts.push_back(chamfered_box({100, -50, 250}, {200, 50, 270}, 3));
  parts.push_back(revolved({{0, 0, 0}, {45, 0, 0}, {14, 0, 60}, {0, 0, 60}}, {150, 0, 270}));  // boot
  parts.push_back(cylinder({150, 0, 270}, {0, 0, 1}, 12, 320));
  parts.push_back(sphere({150, 0, 600}, 22));
  return compound(parts);
}

TopoDS_Shape hand_brake() {
  std::vector<TopoDS_Shape> parts;
  TopoDS_Shape bracket = chamfered_box({-260, -30, 250}, {-200, 30, 300}, 2);
  parts.push_back(cut(bracket, {cylinder({-230, -40, 280}, {0, 1, 0}, 6, 80)}));
  parts.push_back(bent_tube({{-230, 0, 280}, {-120, 0, 420}, {-60, 0, 590}}, 80, 10, 0));
  const Vec3 top(-60, 0, 590), dir = Vec3(60, 0, 170).normalized();
  parts.push_back(tube(top - 70 * dir, top, 15, 0));  // grip
  parts.push_back(sphere(top, 15));
  return compound(parts);
}

TopoDS_Shape seats() {
  std::vector<TopoDS_Shape> parts;
  for (double side : {-1.0, 1.0}) {
    const double ya = side > 0 ? 180 : -620, yb = ya + 440;
    parts.push_back(rounded_box({-520, ya, 100}, {80, yb, 480}, 40));    // cushion
    parts.push_back(rounded_box({-640, ya, 450}, {-520, yb, 1000}, 40)); // backrest
    parts.push_back(rounded_box({-620, ya + 60, 1000}, {-540, yb - 60, 1110}, 25));  // head rest
    for (double y : {ya + 40, yb - 60}) parts.push_back(box({-480, y, 0}, {40, y + 20, 100}));  // rails
  }
  return compound(parts);
}

}  // namespace

SceneModel build_tunnel_console() {
  SceneModel m;
  m.parts.push_back({"console.stl", true, console()});
  m.parts.push_back({"floor.stl", false, body_in_white()});
  m.parts.push_back({"roof.stl", false, roof()});
  m.parts.push_back({"dashboard.stl", false, dashboard()});
  m.parts.push_back({"gear_selector.stl", false, gear_selector()});
  m.parts.push_back({"hand_brake.stl", false, hand_brake()});
  m.parts.push_back({"seats.stl", false, seats()});
  // Mounted: 2 mm above the tunnel, nose 10 mm behind the dashboard, under its lip.
  m.start = Pose::from_translation({0, 0, 252});
  // Outside the passenger door, turned 25° about z.
  m.goal = Pose::from_axis_angle({0, 0, 1}, 25.0 * std::numbers::pi / 180.0, {0, -1150, 300});
  m.bounds_min = {-1000, -1600, 0};
  m.bounds_max = {1000, 1600, 1400};
  m.clearance = 0.5;
  m.test_deflection = {1.0, 0.328223};
  m.paper_deflection = {0.0126133, 0.0162778};
  m.comment =
      "tunnel-console: a car's centre console (a hollow cover) mounted over the transmission\n"
      "tunnel, with the gear lever and the hand brake through its top and its nose under the\n"
      "dashboard's lip. It must move back, lift off the levers, cross over the passenger seat\n"
      "below the roof and leave through the passenger door opening to the goal pose outside.";
  return m;
}

}  // namespace swept::scenes::detail
