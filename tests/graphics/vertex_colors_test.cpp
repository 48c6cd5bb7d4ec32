// Vertex colours (crowns from photographs): NaN where a mesh appended without colours has none,
// the material's colour there, and the colours drawn by the VTK render of an instanced scene.
#include <gtest/gtest.h>

#include <cmath>

#include "graphics/instanced_mesh.hpp"
#include "graphics/render.hpp"
#include "graphics/triangle_mesh.hpp"

namespace fspm::graphics {
namespace {

// A vertical square of side 2 facing -y at the origin, one material, without colours.
TriangleMesh square(Material material) {
  TriangleMesh m;
  m.positions = {{-1, 0, 0}, {1, 0, 0}, {1, 0, 2}, {-1, 0, 2}};
  m.normals.assign(4, Eigen::Vector3f(0, -1, 0));
  m.uvs.assign(4, Eigen::Vector2f::Zero());
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.materials = {material, material};
  return m;
}

void paint(TriangleMesh& m, float r, float g, float b) {
  m.add_attribute("red").assign(m.vertex_count(), r);
  m.add_attribute("green").assign(m.vertex_count(), g);
  m.add_attribute("blue").assign(m.vertex_count(), b);
}

TEST(VertexColors, MeshesWithoutColoursKeepTheirMaterials) {
  TriangleMesh bark = square(Material::kBark), crown = square(Material::kLeaf);
  bark.add_attribute("light").assign(4, 0.5f);
  paint(crown, 0.9f, 0.1f, 0.2f);
  TriangleMesh both = bark;
  both.append(crown);  // the colours come with the second mesh: the first has none
  both.append(square(Material::kLeaf));
  ASSERT_TRUE(both.has_vertex_colors());
  EXPECT_TRUE(std::isnan(both.attribute("red")[0]));
  EXPECT_TRUE(std::isnan(both.attribute("green")[11]));
  EXPECT_EQ(both.attribute("red")[4], 0.9f);
  EXPECT_EQ(both.attribute("light")[4], 0.0f);  // other attributes are 0 where missing
}

TEST(VertexColors, ResolvedFromTheOwnColourOrTheMaterial) {
  TriangleMesh both = square(Material::kBark);
  TriangleMesh crown = square(Material::kLeaf);
  paint(crown, 0.9f, 0.1f, 0.2f);
  both.append(crown);
  both.append(square(Material::kLeaf));
  const auto c = resolved_vertex_colors(both);
  ASSERT_EQ(c.size(), 12u);
  EXPECT_EQ(c[0], material_color(Material::kBark));
  EXPECT_EQ(c[5], (std::array<float, 3>{0.9f, 0.1f, 0.2f}));
  EXPECT_EQ(c[9], material_color(Material::kLeaf));
}

TEST(VertexColors, RenderOfAnInstancedSceneShowsThem) {
  if (!render_available()) GTEST_SKIP() << "built without VTK";
  if (!display_available()) GTEST_SKIP() << "no X display (run under xvfb-run -a)";
  RenderOptions o;
  o.width = 160;
  o.height = 120;
  o.view = View::kFront;
  o.ground = false;
  const auto centre_of = [&](bool painted) {
    InstancedMesh scene;
    scene.meshes.push_back(square(Material::kLeaf));
    if (painted) paint(scene.meshes[0], 0.9f, 0.1f, 0.2f);  // red where leaves are green
    MeshInstance inst;
    inst.translation = {3, 0, 0};  // placed: drawn where the instance puts it
    scene.instances.push_back(inst);
    const Image image = render_scene(scene, o);
    const auto* p = image.pixel(o.width / 2, o.height / 2);
    return std::array<int, 3>{p[0], p[1], p[2]};
  };
  const auto green = centre_of(false), red = centre_of(true);
  EXPECT_GT(green[1], green[0] + 30) << green[0] << " " << green[1] << " " << green[2];
  EXPECT_GT(red[0], red[1] + 60) << red[0] << " " << red[1] << " " << red[2];
  EXPECT_GT(red[0], red[2] + 40);
}

}  // namespace
}  // namespace fspm::graphics
