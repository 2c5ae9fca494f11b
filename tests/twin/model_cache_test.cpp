// Issue 31: a sizing twin's model comes from the model cache and leaves out
// the module's drawing geoms (twin/model_cache.hpp, twin/model_lean.hpp,
// A-TWIN-42); neither may change a single bit of what the twin computes.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "device_logic/process_data.hpp"
#include "device_logic/units.hpp"
#include "tests/twin/twin_helpers.hpp"
#include "twin/load_builder.hpp"
#include "twin/model_cache.hpp"
#include "twin/plant.hpp"
#include "twin/twin.hpp"

namespace sreh {
namespace {

bool same_buffer(const mjModel* a, const mjModel* b) {
  return a->nbuffer == b->nbuffer && std::memcmp(a->buffer, b->buffer, static_cast<std::size_t>(a->nbuffer)) == 0;
}

TEST(ModelCache, ACachedModelIsBitForBitTheCompiledOne) {
  clear_model_cache();
  const BuiltModel first = build_model(InertiaLoad{5000}, {}, 1e-4);
  const BuiltModel again = build_model(InertiaLoad{5000}, {}, 1e-4); // from the cache
  EXPECT_NE(first.model.get(), again.model.get());                    // a copy of its own
  EXPECT_TRUE(same_buffer(first.model.get(), again.model.get()));
  EXPECT_EQ(first.load_inertia_kgm2, again.load_inertia_kgm2);
  clear_model_cache();
  const BuiltModel cold = build_model(InertiaLoad{5000}, {}, 1e-4);
  EXPECT_TRUE(same_buffer(first.model.get(), cold.model.get()));
}

TEST(ModelCache, AnotherLoadOrDriveTrainIsAnotherModel) {
  const BuiltModel a = build_model(InertiaLoad{5000}, {}, 1e-4);
  const BuiltModel b = build_model(InertiaLoad{6000}, {}, 1e-4);
  EXPECT_NE(a.load_inertia_kgm2, b.load_inertia_kgm2);
  MechanicsConstants stiffer = default_module_model().mechanics;
  stiffer.torsional_stiffness_Nm_per_rad *= 1.5;
  const BuiltModel c = build_model(InertiaLoad{5000}, {}, 1e-4, stiffer);
  const int flange = mj_name2id(c.model.get(), mjOBJ_JOINT, "flange");
  EXPECT_EQ(c.model->jnt_stiffness[flange], stiffer.torsional_stiffness_Nm_per_rad);
  EXPECT_NE(a.model->jnt_stiffness[flange], c.model->jnt_stiffness[flange]);
}

TEST(ModelLean, ATwinNeverDrawnHasNoGeoms) {
  const BuiltModel full = build_model(InertiaLoad{5000}, {}, 1e-4);
  const BuiltModel lean = build_model(InertiaLoad{5000}, {}, 1e-4, default_module_model().mechanics,
                                      default_module_model_path(), false);
  EXPECT_EQ(lean.model->ngeom, 0) << "the load's disk an inertial (issue 37): same_dynamics() refused the lean model?";
  EXPECT_GT(full.model->ngeom, lean.model->ngeom);
  EXPECT_EQ(full.load_inertia_kgm2, lean.load_inertia_kgm2);
  // With hard stops the geoms touch: all of them stay.
  const BuiltModel stops = build_model(InertiaLoad{5000}, {HardStop{100}}, 1e-4, default_module_model().mechanics,
                                       default_module_model_path(), false);
  EXPECT_EQ(stops.model->ngeom, full.model->ngeom + 1);
}

// The same PLC program on a drawn twin and on a lean one: every trace row
// and the MuJoCo state bit for bit.
TEST(ModelLean, ALeanTwinRunsBitForBitAsTheDrawnOne) {
  TwinConfig drawn;
  drawn.load = InertiaLoad{8000};
  drawn.mounting_tilt_deg = 90; // gravity acts on the load
  TwinConfig lean = drawn;
  lean.visual_detail = false;
  Twin a(drawn), b(lean);
  for (Twin* t : {&a, &b}) {
    test::write_raw(*t, 65, 4, 8000); // set 1's configured load
    ProcessDataOut pd;
    pd.motor_on = true;
    pd.parameter_set = 1;
    t->set_pd_out(pd);
    for (int i = 0; i < 5; ++i) t->run_cycle();
    pd.move = true;
    pd.target_raw = static_cast<int32_t>(deg_to_wire_counts(135));
    t->set_pd_out(pd);
    for (int i = 0; i < 400; ++i) t->run_cycle();
  }
  ASSERT_EQ(a.trace().size(), b.trace().size());
  for (std::size_t r = 0; r < a.trace().size(); ++r) {
    const TraceRow& x = a.trace()[r];
    const TraceRow& y = b.trace()[r];
    ASSERT_EQ(x.position_deg, y.position_deg) << r;
    ASSERT_EQ(x.torque_Nm, y.torque_Nm) << r;
    ASSERT_EQ(x.velocity_dps, y.velocity_dps) << r;
    ASSERT_EQ(x.temperature_C, y.temperature_C) << r;
    ASSERT_EQ(x.pd_in, y.pd_in) << r;
  }
  EXPECT_EQ(a.plant().rotor_angle_rad(), b.plant().rotor_angle_rad());
  EXPECT_EQ(a.plant().twist_rad(), b.plant().twist_rad());
  EXPECT_EQ(a.plant().velocity_rad_s(), b.plant().velocity_rad_s());
  EXPECT_EQ(a.moves(), b.moves());
  EXPECT_NEAR(a.trace().back().position_deg, 135.0, 0.2); // it did move
}

} // namespace
} // namespace sreh
