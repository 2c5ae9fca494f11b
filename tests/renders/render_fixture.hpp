// Shared fixture: the stand-in module model (test_module.xml) and one
// renderer for the whole suite (OSMesa context creation costs ~0.4 s).
#pragma once
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <memory>
#include <stdexcept>
#include <string>

#include "renders/offscreen.hpp"

namespace sreh::test {

inline std::string test_model_path() { return std::string(SREH_SOURCE_DIR) + "/tests/renders/test_module.xml"; }

struct ModelData {
  mjModel* m = nullptr;
  mjData* d = nullptr;
  ModelData() {
    char error[1000] = "";
    m = mj_loadXML(test_model_path().c_str(), nullptr, error, sizeof error);
    if (!m) throw std::runtime_error(std::string("test model: ") + error);
    d = mj_makeData(m);
    mj_forward(m, d);
  }
  ~ModelData() {
    mj_deleteData(d);
    mj_deleteModel(m);
  }
  ModelData(const ModelData&) = delete;
  ModelData& operator=(const ModelData&) = delete;
  void set_flange(double rad) {
    d->qpos[m->jnt_qposadr[mj_name2id(m, mjOBJ_JOINT, "flange")]] = rad;
    mj_forward(m, d);
  }
};

} // namespace sreh::test
