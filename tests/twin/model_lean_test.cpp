// Issue 37/36: the lean model of a twin never drawn (A-TWIN-42) leaves out
// the two bodies without dynamics, the housing (welded to the world) and
// the set-point ghost (mocap). same_dynamics() compares the moving subtree
// body for body; the lean twin must step bit for bit as the drawn one.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "device_logic/process_data.hpp"
#include "device_logic/units.hpp"
#include "tests/twin/twin_helpers.hpp"
#include "twin/load_builder.hpp"
#include "twin/model_lean.hpp"
#include "twin/plant.hpp"
#include "twin/twin.hpp"

namespace sreh {
namespace {

std::vector<LoadSpec> loads() {
  return {NoLoad{}, InertiaLoad{5000}, DiskLoad{0.4, 0.04}, RingLoad{0.3, 0.02, 0.04}, BoxLoad{0.2, 0.05, 0.03, 0.02},
          ArmLoad{0.1, 0.08, 0.05}, MjcfLoad{std::string(SREH_SOURCE_DIR) + "/models/loads/gripper.xml"},
          AssemblyLoad{{LoadPart{DiskLoad{0.2, 0.03}, {0, 0, 0.005}, {}, "disk", "disk"},
                        LoadPart{BoxLoad{0.1, 0.02, 0.02, 0.02}, {0.05, 0, 0.01}, {0, 0, 30}, "block", "block"},
                        LoadPart{MeshPart{std::string(SREH_SOURCE_DIR) + "/tests/twin/data/cube20_binary.stl", 0.05, 0, 0.001},
                                 {-0.03, 0.01, 0.02}, {10, 0, 0}, "cube", "cube"}},
                       "assembly"}};
}

BuiltModel lean_model(const LoadSpec& load) {
  return build_model(load, {}, 1e-4, default_module_model().mechanics, default_module_model_path(), false);
}

MjModelPtr copy_of(const mjModel* m) { return MjModelPtr(mj_copyModel(nullptr, m)); }

TEST(ModelLean, TheHousingAndTheGhostBodiesAndEveryGeomAreLeftOut) {
  for (const LoadSpec& load : loads()) {
    SCOPED_TRACE(describe_load(load));
    const BuiltModel full = build_model(load, {}, 1e-4);
    const BuiltModel lean = lean_model(load);
    const mjModel* m = lean.model.get();
    EXPECT_EQ(m->nbody, full.model->nbody - 2) << "same_dynamics() refused the lean model?";
    EXPECT_LT(mj_name2id(m, mjOBJ_BODY, "housing"), 0);
    EXPECT_LT(mj_name2id(m, mjOBJ_BODY, "setpoint_ghost"), 0);
    EXPECT_EQ(m->nmocap, 0);
    EXPECT_EQ(m->ngeom, 0); // the load's shapes are inertials (issue 37), the LED band is gone
    EXPECT_GT(full.model->ngeom, 0);
    EXPECT_TRUE(same_dynamics(full.model.get(), m));
    EXPECT_TRUE(same_dynamics(m, full.model.get()));
    EXPECT_EQ(full.load_inertia_kgm2, lean.load_inertia_kgm2);
    EXPECT_EQ(full.axis_inertia_kgm2, lean.axis_inertia_kgm2);
  }
}

TEST(ModelLean, SameDynamicsRejectsAMovingSubtreeThatDiffers) {
  const BuiltModel full = build_model(DiskLoad{0.4, 0.04}, {}, 1e-4);
  const BuiltModel lean = lean_model(DiskLoad{0.4, 0.04});
  const mjModel* f = full.model.get();
  const int load_body = mj_name2id(lean.model.get(), mjOBJ_BODY, "load");
  const int flange_body = mj_name2id(lean.model.get(), mjOBJ_BODY, "flange");
  ASSERT_GE(load_body, 0);
  ASSERT_GE(flange_body, 0);

  MjModelPtr heavier = copy_of(lean.model.get()); // the load's mass one bit more
  heavier->body_mass[load_body] = std::nextafter(heavier->body_mass[load_body], 1.0);
  EXPECT_FALSE(same_dynamics(f, heavier.get()));
  MjModelPtr moved = copy_of(lean.model.get()); // the load 1 um off the flange
  moved->body_pos[3 * load_body] += 1e-6;
  EXPECT_FALSE(same_dynamics(f, moved.get()));
  MjModelPtr turned = copy_of(lean.model.get()); // the flange's inertia turned
  turned->body_iquat[4 * flange_body] = std::nextafter(turned->body_iquat[4 * flange_body], 0.0);
  EXPECT_FALSE(same_dynamics(f, turned.get()));
  MjModelPtr stiffer = copy_of(lean.model.get());
  stiffer->jnt_stiffness[mj_name2id(stiffer.get(), mjOBJ_JOINT, "flange")] *= 2;
  EXPECT_FALSE(same_dynamics(f, stiffer.get()));
  MjModelPtr touching = copy_of(lean.model.get()); // contacts on: geoms take part
  touching->opt.disableflags &= ~mjDSBL_CONTACT;
  EXPECT_FALSE(same_dynamics(touching.get(), touching.get()));

  // A body welded to the world may differ: the housing placed elsewhere.
  MjModelPtr housing_moved = copy_of(f);
  const int housing = mj_name2id(f, mjOBJ_BODY, "housing");
  ASSERT_GE(housing, 0);
  housing_moved->body_pos[3 * housing + 2] += 0.01;
  EXPECT_TRUE(same_dynamics(housing_moved.get(), lean.model.get()));
}

// The rotor hung from the housing instead of the world: the same numbers
// here (the housing sits at the origin), but a moving subtree below a body
// welded to the world is another tree, and not compared as alike.
TEST(ModelLean, SameDynamicsRejectsARotorHungFromTheHousing) {
  std::string xml = compose_model_xml(InertiaLoad{5000}, {});
  const std::string housing_end = "material=\"housing_dark\"/>\n    </body>";
  const std::string ghost_start = "    <!-- planned setpoint";
  const std::size_t end = xml.find(housing_end);
  ASSERT_NE(end, std::string::npos);
  xml.erase(end + housing_end.size() - 7, 7); // the housing's </body> ...
  const std::size_t ghost = xml.find(ghost_start);
  ASSERT_NE(ghost, std::string::npos);
  xml.insert(ghost, "</body>\n"); // ... after the rotor
  MjModelPtr nested = compile_mjcf(xml, "nested");
  MjModelPtr plain = compile_mjcf(compose_model_xml(InertiaLoad{5000}, {}), "plain");
  for (mjModel* m : {nested.get(), plain.get()}) m->opt.disableflags |= mjDSBL_CONTACT;
  const int rotor = mj_name2id(nested.get(), mjOBJ_BODY, "rotor");
  ASSERT_EQ(nested->body_parentid[rotor], mj_name2id(nested.get(), mjOBJ_BODY, "housing"));
  EXPECT_TRUE(same_dynamics(plain.get(), plain.get()));
  EXPECT_FALSE(same_dynamics(plain.get(), nested.get()));
  EXPECT_FALSE(same_dynamics(nested.get(), nested.get())); // below a static body: never compared as alike
}

// The same PLC program, horizontal axis (gravity acts on the load), on a
// drawn twin and a lean one, for several loads: every trace row and the
// MuJoCo state bit for bit.
TEST(ModelLean, ALeanTwinStepsBitForBitAsTheDrawnOneForEveryLoad) {
  for (const LoadSpec& load : loads()) {
    SCOPED_TRACE(describe_load(load));
    TwinConfig drawn;
    drawn.load = load;
    drawn.mounting_tilt_deg = 90;
    TwinConfig lean = drawn;
    lean.visual_detail = false;
    Twin a(drawn), b(lean);
    ASSERT_EQ(b.plant().model()->nbody, a.plant().model()->nbody - 2);
    for (Twin* t : {&a, &b}) {
      test::write_raw(*t, 65, 4, static_cast<uint16_t>(std::min(15000.0, t->load_inertia_gcm2() + 1)));
      ProcessDataOut pd;
      pd.motor_on = true;
      pd.parameter_set = 1;
      t->set_pd_out(pd);
      for (int i = 0; i < 5; ++i) t->run_cycle();
      pd.move = true;
      pd.target_raw = static_cast<int32_t>(deg_to_wire_counts(120));
      t->set_pd_out(pd);
      for (int i = 0; i < 250; ++i) t->run_cycle();
    }
    ASSERT_EQ(a.trace().size(), b.trace().size());
    for (std::size_t r = 0; r < a.trace().size(); ++r) {
      ASSERT_EQ(a.trace()[r].position_deg, b.trace()[r].position_deg) << r;
      ASSERT_EQ(a.trace()[r].torque_Nm, b.trace()[r].torque_Nm) << r;
      ASSERT_EQ(a.trace()[r].velocity_dps, b.trace()[r].velocity_dps) << r;
      ASSERT_EQ(a.trace()[r].temperature_C, b.trace()[r].temperature_C) << r;
      ASSERT_EQ(a.trace()[r].pd_in, b.trace()[r].pd_in) << r;
    }
    EXPECT_EQ(a.moves(), b.moves());
    EXPECT_EQ(a.plant().rotor_angle_rad(), b.plant().rotor_angle_rad());
    EXPECT_EQ(a.plant().twist_rad(), b.plant().twist_rad());
    EXPECT_EQ(a.plant().rotor_velocity_rad_s(), b.plant().rotor_velocity_rad_s());
    EXPECT_EQ(a.plant().gravity_torque_Nm(), b.plant().gravity_torque_Nm());
    EXPECT_EQ(a.plant().ghost_angle_rad(), b.plant().ghost_angle_rad()); // kept, though nothing draws it
    EXPECT_EQ(a.plant().led_band_rgba(), b.plant().led_band_rgba());
    EXPECT_GT(std::abs(a.trace().back().position_deg), 60.0); // it did move
    // The lean model's figures are the coarse model's, bit for bit (a
    // sizing check takes them from the coarse one when it is cached).
    const BuiltModel coarse = check_load(load);
    const BuiltModel lean_model = build_model(load, {}, 1e-4, default_module_model().mechanics,
                                              default_module_model_path(), false);
    EXPECT_EQ(coarse.load_inertia_kgm2, lean_model.load_inertia_kgm2);
    EXPECT_EQ(coarse.axis_inertia_kgm2, lean_model.axis_inertia_kgm2);
    EXPECT_LT(lean_model.model->nbody, coarse.model->nbody); // the lean one indeed
  }
}

} // namespace
} // namespace sreh
