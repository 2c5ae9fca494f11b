// What the off-screen renderer adds to or sets in MuJoCo's scene besides
// the model (issue 29, 31): the degree scale on the housing (A-RENDERS-15),
// clipping planes in metres and the test whether the floor fills the view
// (A-RENDERS-17). Internal to renders/.
#pragma once
#include <mujoco/mujoco.h>

#include <optional>

#include "renders/offscreen.hpp" // flange_angle_rad

namespace sreh {

// Ids looked up once by name; -1 where the model has none.
struct SceneIds {
  int flange_jnt = -1;
  int housing_geom = -1; // the degree scale lies on its top face
  int collar_geom = -1;
  int ghost_body = -1;
};

void add_degree_scale(const mjModel* m, const mjData* d, mjvScene& scn, const SceneIds& ids, std::optional<double> ghost_rad,
                      bool pointer_labels);
// True when nothing of the model lies between the scene's camera and `p`.
bool seen_by_camera(const mjModel* m, const mjData* d, const mjvScene& scn, int ghost_body, const mjtNum p[3]);
void set_clip_planes(mjvScene& scn);
// `aspect`: the frame's width / height.
bool planes_fill_view(const mjModel* m, const mjData* d, const mjvScene& scn, double aspect);

} // namespace sreh
