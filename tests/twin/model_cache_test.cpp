// Issue 31: a sizing twin's model comes from the model cache and leaves out
// the module's drawing geoms (twin/model_cache.hpp, twin/model_lean.hpp,
// A-TWIN-42); neither may change a single bit of what the twin computes.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

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

} // namespace
} // namespace sreh
