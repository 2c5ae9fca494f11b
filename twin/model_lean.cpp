#include "twin/model_lean.hpp"

#include <charconv>
#include <cstring>
#include <regex>
#include <vector>

namespace sreh {
namespace {

// Arrays of n rows of `width` elements, equal bit for bit.
template <class T>
bool same_rows(const T* a, const T* b, int n, int width = 1) {
  return n == 0 || std::memcmp(a, b, sizeof(T) * static_cast<std::size_t>(n) * static_cast<std::size_t>(width)) == 0;
}

// The bodies that take part in the dynamics: those welded to a body with
// degrees of freedom (the rotor, the flange and the load). The world, what
// is welded to it (the housing) and mocap bodies (the set-point ghost) only
// have poses: with contacts off no force reaches a dof from them (MuJoCo
// accumulates forces and inertias towards the world only through bodies
// below a joint). rank[i]: the body's place among them, -1 for the others.
struct Moving {
  std::vector<int> ids;
  std::vector<int> rank;
};

Moving moving_bodies(const mjModel* m) {
  Moving out;
  out.rank.assign(static_cast<std::size_t>(m->nbody), -1);
  for (int i = 1; i < m->nbody; ++i) {
    const int weld = m->body_weldid[i];
    if (weld == 0 || m->body_dofnum[weld] == 0) continue;
    out.rank[static_cast<std::size_t>(i)] = static_cast<int>(out.ids.size());
    out.ids.push_back(i);
  }
  return out;
}

// A body id of model a and one of model b name the same body: both the
// world, or both the same moving body.
bool same_body(const Moving& a, int ia, const Moving& b, int ib) {
  if (ia == 0 || ib == 0) return ia == 0 && ib == 0;
  if (ia < 0 || ib < 0) return ia == ib;
  const int ra = a.rank[static_cast<std::size_t>(ia)], rb = b.rank[static_cast<std::size_t>(ib)];
  return ra >= 0 && ra == rb;
}

// The moving subtree alike body for body: hung from the same parent (the
// world or the same moving body), the same joints, placement and inertial.
bool same_tree(const mjModel* a, const Moving& ma, const mjModel* b, const Moving& mb) {
  if (a->njnt != b->njnt || a->nq != b->nq || a->nv != b->nv || a->nu != b->nu || a->neq != b->neq ||
      a->nM != b->nM || ma.ids.size() != mb.ids.size()) {
    return false;
  }
  for (std::size_t k = 0; k < ma.ids.size(); ++k) {
    const int i = ma.ids[k], j = mb.ids[k];
    const auto row = [](auto* base, int at, int width) { return base + static_cast<std::ptrdiff_t>(at) * width; };
    if (!same_body(ma, a->body_parentid[i], mb, b->body_parentid[j]) ||
        !same_body(ma, a->body_rootid[i], mb, b->body_rootid[j]) ||
        !same_body(ma, a->body_weldid[i], mb, b->body_weldid[j]) || a->body_mocapid[i] != b->body_mocapid[j] ||
        a->body_jntnum[i] != b->body_jntnum[j] || a->body_jntadr[i] != b->body_jntadr[j] ||
        a->body_dofnum[i] != b->body_dofnum[j] || a->body_dofadr[i] != b->body_dofadr[j] ||
        a->body_simple[i] != b->body_simple[j] || a->body_sameframe[i] != b->body_sameframe[j] ||
        !same_rows(row(a->body_pos, i, 3), row(b->body_pos, j, 3), 1, 3) ||
        !same_rows(row(a->body_quat, i, 4), row(b->body_quat, j, 4), 1, 4) ||
        !same_rows(row(a->body_ipos, i, 3), row(b->body_ipos, j, 3), 1, 3) ||
        !same_rows(row(a->body_iquat, i, 4), row(b->body_iquat, j, 4), 1, 4) ||
        !same_rows(a->body_mass + i, b->body_mass + j, 1) ||
        !same_rows(a->body_subtreemass + i, b->body_subtreemass + j, 1) ||
        !same_rows(row(a->body_inertia, i, 3), row(b->body_inertia, j, 3), 1, 3) ||
        !same_rows(row(a->body_invweight0, i, 2), row(b->body_invweight0, j, 2), 1, 2)) {
      return false;
    }
  }
  return true;
}

bool same_joints(const mjModel* a, const Moving& ma, const mjModel* b, const Moving& mb) {
  const int j = a->njnt, v = a->nv;
  for (int i = 0; i < j; ++i) {
    if (!same_body(ma, a->jnt_bodyid[i], mb, b->jnt_bodyid[i])) return false;
  }
  for (int i = 0; i < v; ++i) {
    if (!same_body(ma, a->dof_bodyid[i], mb, b->dof_bodyid[i])) return false;
  }
  return same_rows(a->jnt_type, b->jnt_type, j) && same_rows(a->jnt_qposadr, b->jnt_qposadr, j) &&
         same_rows(a->jnt_dofadr, b->jnt_dofadr, j) && same_rows(a->jnt_limited, b->jnt_limited, j) &&
         same_rows(a->jnt_pos, b->jnt_pos, j, 3) && same_rows(a->jnt_axis, b->jnt_axis, j, 3) &&
         same_rows(a->jnt_stiffness, b->jnt_stiffness, j) && same_rows(a->jnt_range, b->jnt_range, j, 2) &&
         same_rows(a->jnt_solref, b->jnt_solref, j, mjNREF) && same_rows(a->jnt_solimp, b->jnt_solimp, j, mjNIMP) &&
         same_rows(a->qpos0, b->qpos0, a->nq) && same_rows(a->qpos_spring, b->qpos_spring, a->nq) &&
         same_rows(a->dof_jntid, b->dof_jntid, v) && same_rows(a->dof_parentid, b->dof_parentid, v) &&
         same_rows(a->dof_Madr, b->dof_Madr, v) && same_rows(a->dof_simplenum, b->dof_simplenum, v) &&
         same_rows(a->dof_armature, b->dof_armature, v) && same_rows(a->dof_damping, b->dof_damping, v) &&
         same_rows(a->dof_frictionloss, b->dof_frictionloss, v) && same_rows(a->dof_invweight0, b->dof_invweight0, v) &&
         same_rows(a->dof_M0, b->dof_M0, v) && same_rows(a->dof_solref, b->dof_solref, v, mjNREF) &&
         same_rows(a->dof_solimp, b->dof_solimp, v, mjNIMP);
}

// Joint transmissions and joint equalities only (what the module has):
// their ids are joints, alike in both models; anything else is compared
// conservatively as not alike.
bool same_actuators_and_equalities(const mjModel* a, const mjModel* b) {
  const int u = a->nu, e = a->neq;
  for (int i = 0; i < u; ++i) {
    if (a->actuator_trntype[i] != mjTRN_JOINT || b->actuator_trntype[i] != mjTRN_JOINT) return false;
  }
  for (int i = 0; i < e; ++i) {
    if (a->eq_type[i] != mjEQ_JOINT || b->eq_type[i] != mjEQ_JOINT) return false;
  }
  return same_rows(a->actuator_trnid, b->actuator_trnid, u, 2) &&
         same_rows(a->actuator_dyntype, b->actuator_dyntype, u) && same_rows(a->actuator_gaintype, b->actuator_gaintype, u) &&
         same_rows(a->actuator_biastype, b->actuator_biastype, u) && same_rows(a->actuator_gear, b->actuator_gear, u, 6) &&
         same_rows(a->actuator_gainprm, b->actuator_gainprm, u, mjNGAIN) &&
         same_rows(a->actuator_biasprm, b->actuator_biasprm, u, mjNBIAS) &&
         same_rows(a->actuator_ctrllimited, b->actuator_ctrllimited, u) &&
         same_rows(a->actuator_ctrlrange, b->actuator_ctrlrange, u, 2) && same_rows(a->actuator_length0, b->actuator_length0, u) &&
         same_rows(a->eq_obj1id, b->eq_obj1id, e) && same_rows(a->eq_obj2id, b->eq_obj2id, e) &&
         same_rows(a->eq_active, b->eq_active, e) && same_rows(a->eq_data, b->eq_data, e, mjNEQDATA) &&
         same_rows(a->eq_solref, b->eq_solref, e, mjNREF) && same_rows(a->eq_solimp, b->eq_solimp, e, mjNIMP);
}

std::string text(double v) {
  char buf[32];
  const auto res = std::to_chars(buf, buf + sizeof buf, v); // shortest form that reads back bit for bit
  return std::string(buf, res.ptr);
}

// The inertial MuJoCo computed for body `i`, as MJCF.
std::string inertial_xml(const mjModel* m, int i) {
  const mjtNum* p = m->body_ipos + 3 * i;
  const mjtNum* q = m->body_iquat + 4 * i;
  const mjtNum* d = m->body_inertia + 3 * i;
  return "<inertial pos=\"" + text(p[0]) + " " + text(p[1]) + " " + text(p[2]) + "\" quat=\"" + text(q[0]) + " " +
         text(q[1]) + " " + text(q[2]) + " " + text(q[3]) + "\" mass=\"" + text(m->body_mass[i]) + "\" diaginertia=\"" +
         text(d[0]) + " " + text(d[1]) + " " + text(d[2]) + "\"/>";
}

// Issue 37: the geoms of the moving bodies (the flange's drawing and the
// load's shapes) out, each moving body with mass given the inertial MuJoCo
// derived for it in `compiled` (the model of this very text) instead. Body
// ids are the order of the <body> tags in the text (MuJoCo numbers bodies
// depth first, as written).
std::string without_moving_geoms(const std::string& xml, const mjModel* compiled) {
  static const std::regex comment(R"re(<!--[\s\S]*?-->)re");
  static const std::regex element(R"re(<body\b[^>]*?(/?)>|</body>|<geom\b[^>]*?/>|<geom\b[^>]*>[\s\S]*?</geom>|<inertial\b)re");
  const std::string plain = std::regex_replace(xml, comment, "");
  const Moving moving = moving_bodies(compiled);
  auto replaced = [&](int body) {
    return body > 0 && body < compiled->nbody && moving.rank[static_cast<std::size_t>(body)] >= 0 &&
           compiled->body_mass[body] > 0;
  };
  // First pass: which bodies carry an <inertial> of their own (it stays, and
  // their geoms never counted).
  std::vector<char> has_inertial(static_cast<std::size_t>(compiled->nbody), 0);
  int next = 1;
  std::vector<int> open{0};
  for (auto it = std::sregex_iterator(plain.begin(), plain.end(), element); it != std::sregex_iterator(); ++it) {
    const std::string tag = it->str();
    if (tag.rfind("<body", 0) == 0) {
      if ((*it)[1].length() == 0) open.push_back(next);
      ++next;
    } else if (tag == "</body>") {
      if (open.size() > 1) open.pop_back();
    } else if (tag == "<inertial" && open.back() < compiled->nbody) {
      has_inertial[static_cast<std::size_t>(open.back())] = 1;
    }
  }
  if (next != compiled->nbody) return xml; // the text is not this model's: unchanged
  // Second pass: the geoms of replaced bodies out, their inertials in.
  std::string out;
  std::size_t last = 0;
  next = 1;
  open.assign(1, 0);
  for (auto it = std::sregex_iterator(plain.begin(), plain.end(), element); it != std::sregex_iterator(); ++it) {
    const std::string tag = it->str();
    const auto at = static_cast<std::size_t>(it->position(0));
    const auto after = at + static_cast<std::size_t>(it->length(0));
    if (tag.rfind("<body", 0) == 0) {
      const int body = next++;
      out += plain.substr(last, after - last);
      last = after;
      if ((*it)[1].length() == 0) {
        open.push_back(body);
        if (replaced(body) && !has_inertial[static_cast<std::size_t>(body)]) out += inertial_xml(compiled, body);
      }
    } else if (tag == "</body>") {
      if (open.size() > 1) open.pop_back();
    } else if (tag.rfind("<geom", 0) == 0 && replaced(open.back())) {
      out += plain.substr(last, at - last);
      last = after;
    }
  }
  return out + plain.substr(last);
}

std::string without_drawing_geoms(const std::string& xml) {
  static const std::regex drawing(
      R"re(<geom\s+name="(table|floor_[nsew]|plate|housing|connector|collar|flange|bore|mark|stop_lug|ghost_pointer|ghost_tip)"[^>]*/>)re");
  // Lights and cameras too: mj_camlight places them in every step (~4 % of
  // a sizing run's CPU time, issue 37); nothing else in mj_step reads them.
  static const std::regex light_or_camera(R"re(<(light|camera)\s[^>]*/>)re");
  return std::regex_replace(std::regex_replace(xml, drawing, ""), light_or_camera, "");
}

} // namespace

std::string lean_xml(const std::string& xml, const mjModel* compiled) {
  // The two bodies without dynamics (issue 37): the housing, welded to the
  // world, with its LED band (Plant keeps the LED's colour itself when the
  // model has no band), and the set-point ghost, a mocap body
  // (Plant::set_ghost_angle then only keeps the angle). A body holding
  // another is left alone.
  static const std::regex housing(R"re(<body\s+name="housing"[^>]*>(?:(?!<body)[\s\S])*?</body>)re");
  static const std::regex ghost(R"re(<body\s+name="setpoint_ghost"[^>]*>(?:(?!<body)[\s\S])*?</body>)re");
  const std::string fewer = without_drawing_geoms(without_moving_geoms(xml, compiled));
  return std::regex_replace(std::regex_replace(fewer, housing, ""), ghost, "");
}

bool same_dynamics(const mjModel* a, const mjModel* b) {
  // Nothing else in mj_step reads the model when there are no tendons,
  // sensors or contacts; with any of them the models are not compared.
  const auto plain = [](const mjModel* m) {
    return m->ntendon == 0 && m->nsensor == 0 && (m->opt.disableflags & mjDSBL_CONTACT) != 0;
  };
  if (!plain(a) || !plain(b)) return false;
  const Moving ma = moving_bodies(a), mb = moving_bodies(b);
  return same_tree(a, ma, b, mb) && same_joints(a, ma, b, mb) && same_actuators_and_equalities(a, b) &&
         std::memcmp(&a->opt, &b->opt, sizeof(mjOption)) == 0 && a->stat.meaninertia == b->stat.meaninertia;
}

} // namespace sreh
