#include "models/heightspan/heightspan_section.h"

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "models/core/config/fields.h"
#include "models/core/config/scene_loader.h"
#include "models/ground/ground_section.h"
#include "tests/support/refused_field.h"

namespace repose {
namespace {

const char* const kScene = R"(
name: t
time: {step_s: 0.1, duration_s: 1}
ground: {extent_m: [0.1, 0.1], cell_size_m: 0.01, initial_height: {kind: flat, height_m: 0.01}}
objects:
  - {name: plate, shape: box, half_extents_m: [0.02, 0.02, 0.005], motion: [{time_s: 0, position_m: [0.05, 0.05, 0.05]}]}
heightspan: {near_ground_cells: 2, holds_material: {plate: true}}
)";

Scene load(const std::string& text) {
  return load_scene_from_string(text, "/tmp/t.yaml", {ground_model_section_type(), heightspan_section_type()});
}

TEST(HeightSpanSection, ReadsOptionsAndWhichObjectsHoldMaterial) {
  const Scene s = load(kScene);
  const HeightSpanSection& h = heightspan_section(s);
  EXPECT_EQ(h.options.near_ground_cells, 2.0);
  EXPECT_EQ(h.holds_material.at("plate"), true);
  EXPECT_EQ(h.options.frame_interval_s, HeightSpanSpec{}.frame_interval_s);
}

TEST(HeightSpanSection, RefusesUnknownObjectsAndKeysAndBadValues) {
  std::string text = kScene;
  EXPECT_THROW(load(text.replace(text.find("{plate: true}"), 13, "{ball: true}")), InputError);
  text = kScene;
  EXPECT_THROW(load(text.replace(text.find("near_ground_cells: 2"), 20, "near_groundcells: 2")), InputError);
  text = kScene;
  try {
    load(text.replace(text.find("near_ground_cells: 2"), 20, "max_substep_cells: 0"));
    FAIL() << "accepted max_substep_cells: 0";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("max_substep_cells"), std::string::npos) << e.what();
  }
}

TEST(HeightSpanSection, ValidateNamesTheField) {
  HeightSpanSpec spec;
  spec.bulk_density_kg_m3 = -1.0;
  EXPECT_EQ(testing::refused_field(spec), "bulk_density_kg_m3");
  spec = {};
  spec.max_substep_angle_rad = 0.0;
  EXPECT_THROW(validate(spec), FieldError);
  spec = {};
  spec.particle_spread_m_s = std::nan("");
  EXPECT_THROW(validate(spec), FieldError);
  for (const double speed : {-0.1, 101.0, std::nan("")}) {
    spec = {};
    spec.release_speed_m_s = speed;
    EXPECT_EQ(testing::refused_field(spec), "release_speed_m_s") << speed;
  }
  EXPECT_EQ(HeightSpanSpec{}.release_speed_m_s, 0.0);  // the default: the object's own velocity alone
  for (const double fraction : {-0.1, 1.1, std::nan("")}) {
    spec = {};
    spec.press_wedge_fraction = fraction;
    EXPECT_EQ(testing::refused_field(spec), "press_wedge_fraction") << fraction;
  }
  EXPECT_EQ(HeightSpanSpec{}.press_wedge_fraction, 0.0);  // the default: what pressing compresses stays compressed
  spec = {};
  spec.intake_layer_m = 0.0;  // a lip that takes in nothing would never fill: refused
  EXPECT_EQ(testing::refused_field(spec), "intake_layer_m");
  EXPECT_EQ(HeightSpanSpec{}.intake_layer_m, 1e6);  // the default: no limit
  for (const double fraction : {0.0, 1.1, std::nan("")}) {  // 0 would never fill either
    spec = {};
    spec.intake_fraction = fraction;
    EXPECT_EQ(testing::refused_field(spec), "intake_fraction") << fraction;
  }
  EXPECT_EQ(HeightSpanSpec{}.intake_fraction, 1.0);  // the default: all
  for (const double fraction : {-0.1, 1.1, std::nan("")}) {
    spec = {};
    spec.wedge_fraction = fraction;
    EXPECT_EQ(testing::refused_field(spec), "wedge_fraction") << fraction;
  }
  EXPECT_EQ(HeightSpanSpec{}.wedge_fraction, 0.0);  // the default: compressed, as the ground model does
  EXPECT_EQ(HeightSpanSpec{}.wedge_source, HeightSpanSpec::WedgeSource::kCompression);  // as session 17's
}

TEST(HeightSpanSection, RefusesALipWedgeFractionOutsideItsRangeOrWithoutTheSplitSource) {
  HeightSpanSpec spec;
  spec.wedge_source = HeightSpanSpec::WedgeSource::kSplit;
  for (const double fraction : {-0.1, 1.1, std::nan("")}) {
    spec.lip_wedge_fraction = fraction;
    EXPECT_EQ(testing::refused_field(spec), "lip_wedge_fraction") << fraction;
  }
  spec.lip_wedge_fraction = 0.4;
  EXPECT_NO_THROW(validate(spec));
  for (const auto source : {HeightSpanSpec::WedgeSource::kCompression, HeightSpanSpec::WedgeSource::kLip,
                            HeightSpanSpec::WedgeSource::kBoth}) {
    spec.wedge_source = source;  // the others take wedge_fraction: a lip fraction there would be ignored
    EXPECT_EQ(testing::refused_field(spec), "lip_wedge_fraction");
  }
  spec.lip_wedge_fraction = 0.0;
  EXPECT_NO_THROW(validate(spec));
  EXPECT_EQ(HeightSpanSpec{}.lip_wedge_fraction, 0.0);
}

TEST(HeightSpanSection, RefusesAPressFractionOutsideItsRange) {
  for (const double fraction : {-0.1, 1.1, std::nan("")}) {
    HeightSpanSpec spec;
    spec.press_fraction = fraction;
    EXPECT_EQ(testing::refused_field(spec), "press_fraction") << fraction;
  }
  EXPECT_EQ(HeightSpanSpec{}.press_fraction, 0.0);  // the default: compressed, as the ground model does
}

TEST(HeightSpanSection, RefusesASideCutOutsideItsRange) {
  for (const double width_m : {-0.001, 0.11, std::nan("")}) {
    HeightSpanSpec spec;
    spec.side_cut_m = width_m;
    EXPECT_EQ(testing::refused_field(spec), "side_cut_m") << width_m;
  }
  EXPECT_EQ(HeightSpanSpec{}.side_cut_m, 0.0);  // the default: no cut beside the object
}

TEST(HeightSpanSection, RefusesAShearLayerOutsideItsRange) {
  for (const double thickness_m : {-0.001, 0.051, std::nan("")}) {
    HeightSpanSpec spec;
    spec.shear_layer_m = thickness_m;
    EXPECT_EQ(testing::refused_field(spec), "shear_layer_m") << thickness_m;
  }
  EXPECT_EQ(HeightSpanSpec{}.shear_layer_m, 0.0);  // the default: the underside is the object's own
}

TEST(HeightSpanSection, RefusesAnOverLipShareOutsideItsRangeOrWithoutAWedge) {
  for (const double fraction : {-0.1, 1.1, std::nan("")}) {
    HeightSpanSpec spec;
    spec.wedge_fraction = 1.0;
    spec.over_lip_fraction = fraction;
    EXPECT_EQ(testing::refused_field(spec), "over_lip_fraction") << fraction;
  }
  HeightSpanSpec no_wedge;  // a share of nothing: the user meant something else
  no_wedge.over_lip_fraction = 0.2;
  EXPECT_EQ(testing::refused_field(no_wedge), "over_lip_fraction");
  no_wedge.wedge_fraction = 0.5;
  EXPECT_NO_THROW(validate(no_wedge));
  no_wedge.wedge_source = HeightSpanSpec::WedgeSource::kLip;  // that wedge keeps none of the compression
  EXPECT_EQ(testing::refused_field(no_wedge), "over_lip_fraction");
  EXPECT_EQ(HeightSpanSpec{}.over_lip_fraction, 0.0);  // the default: none
}

TEST(HeightSpanSection, ReadsTheWedgeSourceAndRefusesOtherWords) {
  std::string text = kScene;
  const std::string from = "near_ground_cells: 2";
  const Scene s = load(std::string(kScene).replace(text.find(from), from.size(), "wedge_source: lip"));
  EXPECT_EQ(heightspan_section(s).options.wedge_source, HeightSpanSpec::WedgeSource::kLip);
  const Scene split =
      load(std::string(kScene).replace(text.find(from), from.size(), "wedge_source: split, lip_wedge_fraction: 0.3"));
  EXPECT_EQ(heightspan_section(split).options.wedge_source, HeightSpanSpec::WedgeSource::kSplit);
  EXPECT_EQ(heightspan_section(split).options.lip_wedge_fraction, 0.3);
  EXPECT_THROW(load(text.replace(text.find(from), from.size(), "wedge_source: bucket")), InputError);
}

TEST(HeightSpanSection, WritesWhatItReads) {
  const Scene s = load(kScene);
  YAML::Emitter out;
  heightspan_section(s).write_yaml(out);
  const YAML::Node node = YAML::Load(out.c_str());
  EXPECT_EQ(node["near_ground_cells"].as<double>(), 2.0);
  EXPECT_EQ(node["holds_material"]["plate"].as<bool>(), true);
  EXPECT_NE(heightspan_section(s).summary().find("plate holds"), std::string::npos);
}

}  // namespace
}  // namespace repose
