#pragma once
// The height-span model's section of a scene (`heightspan:`): its options
// (not fitted) and which objects hold material. The materials, alpha, theta,
// sigma and En, are the ground model's (`ground_model:`, read beside this
// one); the spans carry the ground's base material (heightspan_model.h).
//
//   heightspan:
//     near_ground_cells: 1.0        # material on a span whose top is at most this many cells above the
//                                   # ground beside it slides onto the ground; higher, it falls as particles
//     max_substep_cells: 1.0        # substeps so that no object moves more than this many cells per substep
//     max_substep_angle_deg: 5      # ... nor turns more than this per substep
//     bulk_density_kg_m3: 1600      # to report held material as mass (LIGGGHTS reports kg)
//     particle_spread_m_s: 0.02     # std. dev. of the horizontal velocity added to released particles
//     release_speed_m_s: 0          # the horizontal speed material flowing off a span's edge into the air
//                                   # has along the way it flowed, beside the velocity of the object's
//                                   # point there (span_erosion.h): grains sliding down a tipped bucket
//                                   # leave its lip moving. Fitted as heightspan.release_speed_m_s
//     intake_layer_m: 1.0e6         # the thickest layer of ground (m of height) a span's top takes in per
//                                   # cell it advances into while the object moves sideways; the ground above
//                                   # it is pushed ahead of the object (the wedge ahead of a bucket's lip);
//                                   # 1e6: no limit (every bit met goes in). Fitted as heightspan.intake_layer_m
//     intake_fraction: 1            # the share of the ground above a span's top it takes in per cell it
//                                   # advances into while the object moves sideways (before intake_layer_m's
//                                   # limit); the rest is pushed ahead (ground_contact.h: Intake). 1: all.
//                                   # Fitted as heightspan.intake_fraction
//     wedge_fraction: 0             # the fraction of what a held object's drag compresses that it keeps as a
//                                   # wedge ahead of it instead, laid in front of it when it stops dragging
//                                   # (drag_wedge.h); 0: compressed, as the ground model does
//     wedge_source: compression     # what the wedge keeps its fraction of: compression (what the drag's
//                                   # displacement compresses, the wall band) | lip (what the lip pushes
//                                   # ahead, the ground above the intake layer, so it grows with the
//                                   # cut's depth; ground_contact.h) | both (drag_wedge.h) | split (both,
//                                   # the lip's part by its own fraction, lip_wedge_fraction)
//     lip_wedge_fraction: 0         # wedge_source split: the fraction of what the lip pushes ahead kept in
//                                   # the wedge (wedge_fraction is then the compression's); fitted as
//                                   # heightspan.lip_wedge_fraction; refused above 0 with another source
//     press_fraction: 0             # the fraction of what a held object's pressing (lowering into the ground)
//                                   # would compress that it displaces around its contact instead (as the
//                                   # ground model displaces its alpha share); 0: compressed, as the ground
//                                   # model does. Fitted as heightspan.press_fraction (drag_wedge.h)
//     press_wedge_fraction: 0       # the fraction of what a held object's pressing compresses (of what
//                                   # press_fraction leaves compressed) that it keeps in its wedge instead,
//                                   # driven ahead by the drag that follows and laid where it ends (the sand
//                                   # a bucket pushes down as it is lowered into the bed is what its drag
//                                   # then bulldozes; drag_wedge.h); 0: compressed. Fitted as
//                                   # heightspan.press_wedge_fraction
//     side_cut_m: 0                 # while a held object drags, the ground within this distance (m) beside
//                                   # its outermost lanes is cut down to its side walls' lower edge where its
//                                   # lip meets new ground, into its wedge (side_cut.h); 0: none. Fitted as
//                                   # heightspan.side_cut_m
//     over_lip_fraction: 0          # the fraction of what a held object's drag keeps in its wedge from the
//                                   # compression that rolls over its lip into it instead (drag_wedge.h);
//                                   # 0: none. Needs wedge_fraction > 0 and a wedge_source other than lip.
//                                   # Fitted as heightspan.over_lip_fraction
//     shear_layer_m: 0              # the layer of ground (m) beneath a held object's lowest surfaces that
//                                   # it shears off with it: its underside meets the ground this much lower
//                                   # (the grains its bottom drags along; the DEM's trenches are deeper
//                                   # than the bucket's path by a fraction of a grain), so what it cuts
//                                   # there is displaced, compressed and kept in its wedge like the rest
//                                   # of its contact (ground_contact.h: underside_of); 0: none. Fitted as
//                                   # heightspan.shear_layer_m
//     frame_interval_s: 0.1         # rendered frames and frame heights written every this (0: none)
//     span_maps: cpu                # cpu | osmesa: who depth-peels the span maps (span_peeler.h)
//     holds_material: {bucket: true, plate: true, ball: false}
//                                   # per object; absent: meshes that are not convex hold material
//
// The section is optional: a scene without it runs with the defaults.

#include <map>
#include <string>

#include "models/core/config/scene.h"
#include "models/core/config/scene_section.h"
#include "models/core/config/yaml_reader.h"

namespace repose {

struct HeightSpanSpec {
  double near_ground_cells = 1.0;   // [0, 1e6]
  double max_substep_cells = 1.0;   // (0.01, 1e6]
  double max_substep_angle_rad = 0.08726646259971647;  // 5 deg, [0.01, 180] deg
  double bulk_density_kg_m3 = 1600.0;  // (0, 1e5]
  double particle_spread_m_s = 0.02;   // [0, 100]
  double release_speed_m_s = 0.0;      // [0, 100]
  double intake_layer_m = 1e6;         // (0, 1e6]; 1e6: no limit (ground_contact.h)
  double intake_fraction = 1.0;        // (0, 1]; 1: all (ground_contact.h: Intake)
  double wedge_fraction = 0.0;         // [0, 1]; 0: none (drag_wedge.h)
  enum class WedgeSource { kCompression, kLip, kBoth, kSplit };
  WedgeSource wedge_source = WedgeSource::kCompression;  // what wedge_fraction keeps (drag_wedge.h)
  double lip_wedge_fraction = 0.0;     // [0, 1]; above 0 only with kSplit (drag_wedge.h)
  double press_fraction = 0.0;         // [0, 1]; 0: the pressing's compression as the ground model's (drag_wedge.h)
  double press_wedge_fraction = 0.0;   // [0, 1]; 0: the pressing's compression stays compressed (drag_wedge.h)
  double side_cut_m = 0.0;             // [0, 0.1] m; 0: none (side_cut.h)
  double over_lip_fraction = 0.0;      // [0, 1]; 0: none (drag_wedge.h)
  double shear_layer_m = 0.0;          // [0, 0.05] m; 0: none (ground_contact.h: underside_of)
  double frame_interval_s = 0.1;       // [0, 1e6]; 0: no frames
  enum class SpanMaps { kCpu, kOsmesa };
  SpanMaps span_maps = SpanMaps::kCpu;
};

// Throws FieldError naming the field and the rule; the loader and the model
// call this one rule.
void validate(const HeightSpanSpec& spec);

template <class Visitor>
void heightspan_fields(Visitor& v, HeightSpanSpec& s) {
  v.number("near_ground_cells", s.near_ground_cells, Range::any());
  v.number("max_substep_cells", s.max_substep_cells, Range::any());
  v.angle_deg("max_substep_angle_deg", s.max_substep_angle_rad, Range::any());
  v.number("bulk_density_kg_m3", s.bulk_density_kg_m3, Range::any());
  v.number("particle_spread_m_s", s.particle_spread_m_s, Range::any());
  v.number("release_speed_m_s", s.release_speed_m_s, Range::any());
  v.number("intake_layer_m", s.intake_layer_m, Range::any());
  v.number("intake_fraction", s.intake_fraction, Range::any());
  v.number("wedge_fraction", s.wedge_fraction, Range::any());
  using W = HeightSpanSpec::WedgeSource;
  v.choice("wedge_source", s.wedge_source,
           std::vector<std::pair<std::string, W>>{{"compression", W::kCompression}, {"lip", W::kLip}, {"both", W::kBoth},
                                                          {"split", W::kSplit}});
  v.number("lip_wedge_fraction", s.lip_wedge_fraction, Range::any());
  v.number("press_fraction", s.press_fraction, Range::any());
  v.number("press_wedge_fraction", s.press_wedge_fraction, Range::any());
  v.number("side_cut_m", s.side_cut_m, Range::any());
  v.number("over_lip_fraction", s.over_lip_fraction, Range::any());
  v.number("shear_layer_m", s.shear_layer_m, Range::any());
  v.number("frame_interval_s", s.frame_interval_s, Range::any());
  using M = HeightSpanSpec::SpanMaps;
  v.choice("span_maps", s.span_maps, std::vector<std::pair<std::string, M>>{{"cpu", M::kCpu}, {"osmesa", M::kOsmesa}});
}

class HeightSpanSection final : public SceneSection {
 public:
  static constexpr const char* kKey = "heightspan";

  HeightSpanSpec options;
  std::map<std::string, bool> holds_material;  // by object name; absent: decided by shape

  void write_yaml(YAML::Emitter& out) const override;
  std::string summary() const override;
};

// The scene's section, or the defaults when it has none.
const HeightSpanSection& heightspan_section(const Scene& scene);
// A copy of the scene with this section.
Scene with_heightspan(Scene scene, const HeightSpanSection& section);

std::shared_ptr<const SceneSection> read_heightspan_section(const YamlValue& value, const Scene& common);
SectionType heightspan_section_type();

}  // namespace repose
