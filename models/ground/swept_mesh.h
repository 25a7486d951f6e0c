#pragma once
// The volume a translating object sweeps between two poses (the ground
// paper, 3.3, Fig. 3): faces whose outward normal points along the motion
// are placed at the later pose, the others at the earlier pose, and every
// edge between a front and a back face (the silhouette), and every open
// edge, is extruded into a quad joining its two positions. Seen from below,
// the swept mesh's underside is the lowest the object reached between the
// poses, so one collision per frame leaves a continuous furrow.
//
// Only translation is swept: both poses use `to.orientation`; rotating
// objects are substepped by angle instead (ground_step.h).
//
// The mesh is built every step, so what depends on the body alone (which
// face shares each edge, the faces' normals) is computed once per body
// (SweptBody, kept in GroundModel) and a step only classifies faces and
// copies vertices.

#include <vector>

#include "models/core/geometry/triangle_mesh.h"
#include "models/ground/faces_down.h"

namespace repose {

// What the swept mesh needs of a body, computed once.
struct SweptBody {
  // For face f and its edge k (F(f, k) -> F(f, (k + 1) % 3)): the face using
  // that edge reversed, or -1 for an open edge. 3 * face count entries.
  std::vector<int> twin_face;
  // Unnormalised outward normal of each face, in body coordinates.
  std::vector<Eigen::Vector3d> face_normal;
};

SweptBody make_swept_body(const TriangleMesh& body);

// body: in body coordinates; swept: make_swept_body(body). Returns world
// coordinates. When the two positions coincide, the body placed at `to`.
TriangleMesh swept_mesh(const TriangleMesh& body, const SweptBody& swept, const Pose& from, const Pose& to);
// The same, computing make_swept_body(body) first.
TriangleMesh swept_mesh(const TriangleMesh& body, const Pose& from, const Pose& to);

// True when a motion d has no horizontal part (exactly: x and y are zero).
bool is_vertical(const Eigen::Vector3d& d);

// What vertical_sweep_faces_down keeps between calls for one body, so that
// a press or lift neither places every vertex nor tests every face every
// step. At the last orientation and horizontal position, bit for bit: the
// body placed there at height 0 and its box (transformed_vertices adds the
// height last, so x and y are those at any height, and z is that at height
// p.z less p.z, bit for bit when p.z != 0: adding 0 changed at most the
// sign of a zero, which adding p.z erases; rounding keeps the order of z,
// so the box's z is lifted alike), and the faces turned down (the test
// reads x and y alone). And the faces and vertex order made from them at
// the last choice of front faces.
struct VerticalSweepCache {
  bool valid = false;
  Eigen::Quaterniond orientation;
  double x_m = 0.0, y_m = 0.0;
  MatrixX3dR level;  // the body at (x_m, y_m, 0)
  Aabb level_box;
  std::vector<int> turned;  // the faces turned down, in order
  std::vector<char> front;  // per turned face: placed at the later pose
  MatrixX3iR faces;         // into `used`
  std::vector<int> used;    // vertex v < nv at the earlier pose, nv + v at the later, in order of first use
};

// For a vertical motion (is_vertical(to - from)): what a view from below
// sees of the swept mesh, faces_turned(swept_mesh(body, swept, from, to),
// true): the same faces in the same order at the same coordinates, bit for
// bit, on the vertices they use alone (numbered as first used), with the
// bounding box of the whole swept mesh (faces_down.h), found from the body
// at `to` alone: what a step renders, with a quarter of the vertices. The
// silhouette and open-edge quads of a vertical sweep join each edge to
// itself shifted along z, so their x and y are exactly those of the edge:
// they have no area seen along z, and faces_turned drops them; so they are
// not made, and a face is turned alike at both poses. cache: kept
// by the caller for this body (any contents give the same result).
FacesDown vertical_sweep_faces_down(const TriangleMesh& body, const SweptBody& swept, const Pose& from,
                                    const Pose& to, VerticalSweepCache* cache);
FacesDown vertical_sweep_faces_down(const TriangleMesh& body, const SweptBody& swept, const Pose& from,
                                    const Pose& to);

}  // namespace repose
