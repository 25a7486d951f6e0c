#include "models/ground/material_parameters.h"

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "models/ground/ground_model.h"

namespace repose {
namespace {

TEST(MaterialParameters, FourPerDistinctMaterialAppliedByName) {
  Material sand, mud;
  material_preset("sand", &sand);
  material_preset("mud", &mud);
  GroundModel model = make_plain_ground_model(Grid{4, 4, 0.01, 0, 0}, sand);
  model.materials = {sand, mud, sand};  // a second region of sand shares its parameters
  const MaterialParameters p(model);
  ASSERT_EQ(p.infos().size(), 8u);
  EXPECT_EQ(p.infos()[0].name, "sand.alpha");
  EXPECT_EQ(p.infos()[3].name, "sand.drag_compaction_ratio");
  EXPECT_EQ(p.infos()[5].name, "mud.repose_angle_deg");
  std::vector<double> values;
  for (const ParameterInfo& info : p.infos()) values.push_back(info.value_si);
  values[2] = 0.1;  // sand.sigma
  const GroundParams params = p.params_for(model, values);
  EXPECT_EQ(params.materials[0].sigma, 0.1);
  EXPECT_EQ(params.materials[2].sigma, 0.1);
  EXPECT_EQ(params.materials[1].sigma, mud.sigma);
  values[3] = 0.25;  // sand.drag_compaction_ratio
  EXPECT_EQ(p.params_for(model, values).materials[2].drag_compaction_ratio, 0.25);
  EXPECT_EQ(p.params_for(model, values).materials[1].drag_compaction_ratio, 1.0);
  values[2] = 0.5;  // beyond the stability limit
  EXPECT_THROW(p.params_for(model, values), InputError);
}

}  // namespace
}  // namespace repose
