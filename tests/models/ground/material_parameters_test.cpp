#include "models/ground/material_parameters.h"

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "models/ground/ground_model.h"

namespace repose {
namespace {

TEST(MaterialParameters, ThreePerDistinctMaterialAppliedByName) {
  Material sand, mud;
  material_preset("sand", &sand);
  material_preset("mud", &mud);
  GroundModel model = make_plain_ground_model(Grid{4, 4, 0.01, 0, 0}, sand);
  model.materials = {sand, mud, sand};  // a second region of sand shares its parameters
  const MaterialParameters p(model);
  ASSERT_EQ(p.infos().size(), 6u);
  EXPECT_EQ(p.infos()[0].name, "sand.alpha");
  EXPECT_EQ(p.infos()[4].name, "mud.repose_angle_deg");
  std::vector<double> values;
  for (const ParameterInfo& info : p.infos()) values.push_back(info.value_si);
  values[2] = 0.1;  // sand.sigma
  const GroundParams params = p.params_for(model, values);
  EXPECT_EQ(params.materials[0].sigma, 0.1);
  EXPECT_EQ(params.materials[2].sigma, 0.1);
  EXPECT_EQ(params.materials[1].sigma, mud.sigma);
  values[2] = 0.5;  // beyond the stability limit
  EXPECT_THROW(p.params_for(model, values), InputError);
}

}  // namespace
}  // namespace repose
