// The end of the pipeline: the thin-sheet merge, the stage-by-stage Part_decomposer, and the whole
// decomposition of the shipped example meshes against their true parts.
#include <catch2/catch.hpp>

#include <CGAL/Part_decomposition/IO/read_mesh.h>
#include <CGAL/Part_decomposition/Part_decomposer.h>
#include <CGAL/Part_decomposition/decompose.h>
#include <CGAL/Part_decomposition/part_composition.h>
#include <CGAL/Part_decomposition/piece_segmentation.h>
#include <CGAL/Part_decomposition/thin_sheet_merging.h>
#include <CGAL/boost/graph/helpers.h>

#include <boost/property_map/property_map.hpp>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include "segmentation_metrics.h"
#include "shipped_shapes.h"
#include "method_switches.h"
#include "test_shapes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <cstdio>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace PD = CGAL::Part_decomposition;
namespace PDP = CGAL::Part_decomposition::parameters;
using test_shapes::K;
using test_shapes::Mesh;
using test_shapes::Point;
typedef Mesh::Face_index face_descriptor;

namespace {

PD::Input_error error_of(const std::function<void()>& f)
{
  try
  {
    f();
  }
  catch(const PD::Invalid_input& e)
  {
    return e.error();
  }
  FAIL("no Invalid_input thrown");
  return PD::Input_error::NO_FACES;
}

// A WritablePropertyMap without get(): the part of each face, and how often it was written.
struct Write_only_part_map
{
  typedef face_descriptor key_type;
  typedef std::size_t value_type;
  typedef std::size_t reference;
  typedef boost::writable_property_map_tag category;

  std::vector<std::size_t>* part;
  std::vector<int>* writes;

  friend void put(const Write_only_part_map& m, const key_type& f, std::size_t v)
  {
    (*m.part)[std::size_t(f)] = v;
    ++(*m.writes)[std::size_t(f)];
  }
};

// A thin box (or slab) split in two parts by the plane x = 0, or with its top face (z = max) as
// one part and the rest as the other; each part gets a primitive of the given semi-axes and claims
// the inside leaves of its side, of the grid of the distance field at the finest voxel resolution.
struct Sheet_case
{
  Mesh mesh;
  PD::Truncated_signed_distance_field tsdf;
  PD::Superquadric_fitting_result<K> fitting;
  std::vector<std::size_t> part;
  std::vector<std::size_t> part_to_primitive{0, 1};
};

Sheet_case make_sheet_case(double thickness, bool split_by_top_face, const std::array<double, 3>& scales,
                           int finest_resolution = 64)
{
  Sheet_case c;
  c.mesh = test_shapes::make_box(Point(-1, -1, -thickness / 2), Point(1, 1, thickness / 2), 16);
  c.tsdf = PD::compute_tsdf(c.mesh, PD::parameters::voxel_resolutions(std::vector<int>{finest_resolution}));
  c.fitting.normalization = c.tsdf.normalization;
  const PD::Superquadric<K>::Rotation identity = {{1, 0, 0, 0, 1, 0, 0, 0, 1}};
  for(int k = 0; k < 2; ++k)
    c.fitting.primitives.push_back(PD::Superquadric<K>(scales, 1., 1., identity, Point(k ? 0.25 : -0.25, 0, 0)));
  c.fitting.claimed_leaves.resize(2);
  c.fitting.labels.assign(c.tsdf.grid.number_of_leaves(), -1);
  for(std::size_t l = 0; l < c.tsdf.values.size(); ++l)
    if(c.tsdf.values[l] < 0.)
    {
      const std::int32_t k = c.tsdf.grid.center(l)[0] < 0. ? 0 : 1;
      c.fitting.claimed_leaves[std::size_t(k)].push_back(l);
      c.fitting.labels[l] = k;
    }
  for(face_descriptor f : faces(c.mesh))
  {
    double x = 0., z = 0.;
    for(auto v : vertices_around_face(halfedge(f, c.mesh), c.mesh))
    {
      x += c.mesh.point(v).x() / 3.;
      z += c.mesh.point(v).z() / 3.;
    }
    c.part.push_back(split_by_top_face ? (z > thickness / 2 - 1e-9 ? 0 : 1) : (x < 0. ? 0 : 1));
  }
  return c;
}

std::size_t merge(Sheet_case& c)
{
  return PD::merge_thin_sheet_parts(c.mesh, CGAL::make_property_map(c.part), c.part_to_primitive, c.fitting, c.tsdf);
}

} // namespace

TEST_CASE("flat thin parts that meet along smooth edges become one part", "[sheet_merge]")
{
  // 2 x 2 x 0.06: about two voxels thick in the 64^3 grid, the primitives are flat.
  Sheet_case c = make_sheet_case(0.06, false, {{0.5, 0.5, 0.03}});
  const std::size_t n0 = c.fitting.claimed_leaves[0].size(), n1 = c.fitting.claimed_leaves[1].size();
  REQUIRE(n0 > 0);
  REQUIRE(n1 > 0);
  CHECK(merge(c) == 1u);
  CHECK(std::set<std::size_t>(c.part.begin(), c.part.end()) == std::set<std::size_t>{0});
  REQUIRE(c.part_to_primitive.size() == 1u);
  CHECK(c.part_to_primitive[0] == (n1 > n0 ? 1u : 0u)); // the primitive of most claimed leaves
}

TEST_CASE("the sheet merge keeps creases, round primitives and thick parts apart", "[sheet_merge]")
{
  SECTION("the seam runs over the rim of the slab, a crease")
  {
    Sheet_case c = make_sheet_case(0.06, true, {{0.5, 0.5, 0.03}});
    const std::vector<std::size_t> before = c.part;
    CHECK(merge(c) == 2u);
    CHECK(c.part == before);
  }
  SECTION("the primitives are not flat")
  {
    Sheet_case c = make_sheet_case(0.06, false, {{0.5, 0.5, 0.4}});
    CHECK(merge(c) == 2u);
  }
  SECTION("the parts are thick: a 2 x 2 x 0.5 box, 8 voxels deep")
  {
    Sheet_case c = make_sheet_case(0.5, false, {{0.5, 0.5, 0.1}});
    CHECK(merge(c) == 2u);
    CHECK(c.part_to_primitive == std::vector<std::size_t>({0, 1}));
  }
}

TEST_CASE("a sheet's thickness is a length: the same slab is a sheet on the 64^3 and 128^3 grids", "[sheet_merge]")
{
  // 2 x 2 x 0.1: about 3 voxels thick at 64^3 and 6 at 128^3, where its middle lies deeper than
  // 2.5 voxels; a 2 x 2 x 0.5 box stays thick on both grids.
  for(int r : {64, 128})
  {
    Sheet_case slab = make_sheet_case(0.1, false, {{0.5, 0.5, 0.05}}, r);
    CHECK(merge(slab) == 1u);
    Sheet_case box = make_sheet_case(0.5, false, {{0.5, 0.5, 0.1}}, r);
    CHECK(merge(box) == 2u);
  }
}

TEST_CASE("the sheet merge with every default given explicitly gives the default parts", "[sheet_merge][defaults]")
{
  Sheet_case a = make_sheet_case(0.06, false, {{0.5, 0.5, 0.03}});
  Sheet_case b = a;
  const std::size_t na = merge(a);
  const std::size_t nb = PD::merge_thin_sheet_parts(
      b.mesh, CGAL::make_property_map(b.part), b.part_to_primitive, b.fitting, b.tsdf,
      CGAL::parameters::vertex_point_map(get(CGAL::vertex_point, b.mesh))
          .face_index_map(get(CGAL::face_index, b.mesh))
          .geom_traits(K()));
  CHECK(na == 1u);
  CHECK(nb == na);
  CHECK(b.part == a.part);
  CHECK(b.part_to_primitive == a.part_to_primitive);
}

TEST_CASE("the sheet merge refuses a distance field of another frame", "[sheet_merge]")
{
  Sheet_case c = make_sheet_case(0.06, false, {{0.5, 0.5, 0.03}});
  c.fitting.normalization = PD::Normalization({{0., 0., 0.}}, 2. * c.tsdf.normalization.scale());
  CHECK(error_of([&] { merge(c); }) == PD::Input_error::INVALID_PARAMETER);
}

TEST_CASE("the shipped example meshes load and carry one label per face", "[data]")
{
  const std::map<std::string, std::pair<int, int> > expected = {
      {"table", {5, 5}}, {"animal", {6, 8}}, {"dumbbell", {3, 3}}};
  for(const auto& e : expected)
  {
    INFO(e.first);
    const std::string base = std::string(PD_EXAMPLE_DATA_DIR) + "/" + e.first;
    Mesh m;
    const PD::IO::Mesh_file_info info = PD::IO::read_triangle_mesh(base + ".off", m);
    CHECK(info.number_of_input_faces == num_faces(m));
    CHECK(info.number_of_input_faces >= 3000);
    CHECK(info.number_of_input_faces <= 10000);
    CHECK(CGAL::is_closed(m));
    std::ifstream in(base + ".seg");
    REQUIRE(in);
    std::vector<int> labels;
    int l;
    while(in >> l) labels.push_back(l);
    CHECK(labels.size() == info.number_of_input_faces);
    const std::set<int> distinct(labels.begin(), labels.end());
    CHECK(int(distinct.size()) >= e.second.first);
    CHECK(int(distinct.size()) <= e.second.second);
    CHECK(*distinct.begin() == 0);
    CHECK(*distinct.rbegin() == int(distinct.size()) - 1);
  }
}

TEST_CASE("the parts are written once to a write-only map, by decompose() and Part_decomposer", "[decompose][data]")
{
  Mesh m;
  test_shapes::read_shipped_shape("dumbbell", m);
  const std::size_t nf = num_faces(m);
  std::vector<std::size_t> reference(nf);
  const std::size_t K_parts = PD::decompose(m, CGAL::make_property_map(reference));
  REQUIRE(K_parts == 3u);

  std::vector<std::size_t> part(nf, std::size_t(-1));
  std::vector<int> writes(nf, 0);
  CHECK(PD::decompose(m, Write_only_part_map{&part, &writes}) == K_parts);
  CHECK(part == reference);
  CHECK(std::set<int>(writes.begin(), writes.end()) == std::set<int>{1});

  PD::Part_decomposer<Mesh> pd(m);
  pd.compute_prior();
  pd.compute_distance_field();
  pd.fit_primitives();
  pd.over_segment();
  std::fill(part.begin(), part.end(), std::size_t(-1));
  std::fill(writes.begin(), writes.end(), 0);
  CHECK(pd.compose_parts(Write_only_part_map{&part, &writes}) == K_parts);
  CHECK(part == reference);
  CHECK(pd.parts() == reference);
  CHECK(std::set<int>(writes.begin(), writes.end()) == std::set<int>{1});
}

// decompose() rebuilt from the documented stage functions, called in their documented order with
// the same named parameters; `use_pieces` and `keep_residual_patches` are those of `np`.
template <typename NamedParameters>
std::size_t decompose_by_stages(const Mesh& m, bool use_pieces, bool keep_residual_patches, const NamedParameters& np,
                                std::vector<std::size_t>& labels, std::vector<PD::Superquadric<K> >& primitives)
{
  const auto any = [](const std::vector<std::uint8_t>& flags) { return std::count(flags.begin(), flags.end(), 1) > 0; };
  const std::size_t nf = num_faces(m);
  PD::Piece_segmentation pieces;
  bool volume = true;
  if(use_pieces)
  {
    pieces = PD::segment_pieces(m, np);
    volume = any(PD::splittable_pieces(m, pieces, np));
  }
  PD::Hierarchical_prior prior;
  PD::Truncated_signed_distance_field tsdf;
  std::vector<std::uint8_t> volumetric;
  if(volume)
  {
    // the prior shapes the grid of the distance field
    prior = PD::compute_flow_freeze_prior(m, np);
    tsdf = PD::compute_tsdf(m, prior, np);
    if(use_pieces) volume = any(volumetric = PD::volumetric_pieces(m, pieces, tsdf, np));
  }
  PD::Superquadric_fitting_result<K> fitting;
  PD::Volumetric_parts parts;
  if(volume)
  {
    const PD::Fitting_zones zones =
      PD::compute_fitting_zones(prior, tsdf, PD::fitting_resolutions(prior.resolutions), np);
    fitting = PD::fit_superquadrics<CGAL::Sequential_tag, K>(prior, tsdf, zones, np);
    parts.patches.resize(nf);
    PD::over_segment(m, CGAL::make_property_map(parts.patches), np);
    parts.parts.resize(nf);
    parts.part_to_primitive = PD::assign_parts(m, CGAL::make_property_map(parts.patches), fitting.labels, tsdf,
                                               CGAL::make_property_map(parts.parts), np);
    if(keep_residual_patches) PD::separate_residual_patches(m, parts, prior, fitting, np);
    PD::merge_thin_sheet_parts(m, CGAL::make_property_map(parts.parts), parts.part_to_primitive, fitting, tsdf, np);
  }
  const PD::Composed_parts<K> composed = PD::compose_parts(m, pieces, volumetric, parts, fitting, np);
  const PD::Part_hierarchy<K> hierarchy = PD::build_part_hierarchy(m, pieces, composed, np);
  const std::size_t k = hierarchy.level_below_cost(composed.number_of_parts(), PD::defaults::maximum_merge_cost);
  labels = hierarchy.labels(k);
  primitives = hierarchy.primitives(k);
  return k;
}

namespace {

// The same superquadrics, in the same order, to the last bit.
void check_same_primitives(const std::vector<PD::Superquadric<K> >& a, const std::vector<PD::Superquadric<K> >& b)
{
  REQUIRE(a.size() == b.size());
  for(std::size_t k = 0; k < a.size(); ++k)
  {
    CHECK(a[k].scales() == b[k].scales());
    CHECK(a[k].center() == b[k].center());
  }
}

} // namespace

template <typename NamedParameters>
void check_stages_give_decompose(const Mesh& m, bool use_pieces, bool keep_residual_patches, const NamedParameters& np)
{
  std::vector<std::size_t> expected(num_faces(m)), labels;
  std::vector<PD::Superquadric<K> > expected_primitives, primitives;
  const std::size_t K_expected = PD::decompose(
    m, CGAL::make_property_map(expected),
    PDP::combine(np, PDP::primitive_output_iterator(std::back_inserter(expected_primitives))));
  CHECK(test_shapes::count_if_numbered_by_first_face(expected) == K_expected);
  CHECK(decompose_by_stages(m, use_pieces, keep_residual_patches, np, labels, primitives) == K_expected);
  CHECK(labels == expected);
  check_same_primitives(primitives, expected_primitives);
}

TEST_CASE("the stage functions in their documented order give the parts of decompose()", "[decompose][stages][data]")
{
  for(const std::string name : {"animal", "table", "dumbbell"})
  {
    CAPTURE(name);
    Mesh m;
    test_shapes::read_shipped_shape(name, m);
    check_stages_give_decompose(m, true, false, CGAL::parameters::default_values());
  }
  Mesh animal;
  test_shapes::read_shipped_shape("animal", animal);
  check_stages_give_decompose(animal, false, true,
                              switches(&Variant::use_pieces, false, &Variant::keep_residual_patches, true));
  // generated: a bracket the volumetric stages decompose, a sheet that bounds no volume
  check_stages_give_decompose(test_shapes::make_l_bracket(1., 0.7, 0.1, 0.4, 0.02), true, false,
                              CGAL::parameters::default_values());
  check_stages_give_decompose(test_shapes::make_wavy_sheet(24, 0.15), true, false, CGAL::parameters::default_values());
  // the dense grid of the paper
  Mesh dumbbell;
  test_shapes::read_shipped_shape("dumbbell", dumbbell);
  check_stages_give_decompose(dumbbell, true, false, switches(&Variant::adaptive_grid, false));
}

TEST_CASE("a parallel Part_decomposer gives the parts of decompose() and times its stages", "[decompose][stages][data]")
{
  // decompose() runs through the decomposer's stages: the same parts, the over-segmentation beside
  // the volumetric stages
  Mesh m;
  test_shapes::read_shipped_shape("dumbbell", m);
  std::vector<std::size_t> expected(num_faces(m)), parts(num_faces(m));
  PD::decompose<CGAL::Parallel_tag>(m, CGAL::make_property_map(expected), PDP::maximum_merge_cost(0.));
  PD::Part_decomposer<Mesh> pd(m);
  const std::size_t K = pd.compose_parts<CGAL::Parallel_tag>(CGAL::make_property_map(parts));
  CHECK(parts == expected);
  CHECK(test_shapes::count_if_numbered_by_first_face(parts) == K);
  const PD::Stage_timings& t = pd.stage_timings();
  CHECK(t.overlapping);
  for(double seconds : {t.pieces, t.prior, t.tsdf, t.fitting, t.fitting_zones, t.over_segmentation, t.assignment})
    CHECK(seconds > 0.);
  CHECK(t.fitting >= t.fitting_zones);
  CHECK(t.hierarchy == 0.);
  CHECK(t.total == 0.);
  pd.build_hierarchy();
  CHECK(pd.stage_timings().hierarchy > 0.);
  // a stage computed again adds its time
  const double prior = t.prior;
  pd.compute_prior();
  CHECK(pd.stage_timings().prior > prior);
}

TEST_CASE("the thin-sheet merge is a step of Part_decomposer::compose_parts()", "[decompose][sheet_merge][data]")
{
  // The table: its top is a thin slab.
  Mesh m;
  test_shapes::read_shipped_shape("table", m);
  std::vector<std::size_t> merged(num_faces(m)), unmerged(num_faces(m));
  // the parts of the assignment: without the hierarchy's merges
  const std::size_t K_merged =
    PD::decompose(m, CGAL::make_property_map(merged), PDP::combine(switches(&Variant::use_pieces, false), PDP::maximum_merge_cost(0.)));

  PD::Part_decomposer<Mesh> pd(m);
  const std::size_t K_unmerged = pd.compose_parts(CGAL::make_property_map(unmerged),
                                                   switches(&Variant::merge_thin_sheets, false, &Variant::use_pieces, false));
  CHECK(pd.parts() == unmerged);
  CHECK(K_unmerged >= K_merged);
  // the free function on the volumetric parts before the merge
  std::vector<std::size_t> part_to_primitive = pd.volumetric_parts().part_to_primitive;
  std::vector<std::size_t> by_function = pd.volumetric_parts().parts;
  const std::size_t K_function = PD::merge_thin_sheet_parts(m, CGAL::make_property_map(by_function),
                                                            part_to_primitive, pd.fitting(), pd.distance_field());
  CHECK(K_function == K_merged);
  // the same parts, which the composition numbers by smallest face index
  const std::size_t none = std::size_t(-1);
  std::vector<std::size_t> composed_id(K_function, none);
  bool same_parts = true;
  for(std::size_t i = 0; i < merged.size(); ++i)
  {
    std::size_t& id = composed_id[by_function[i]];
    if(id == none) id = merged[i];
    same_parts = same_parts && id == merged[i];
  }
  CHECK(same_parts);
  CHECK(std::set<std::size_t>(composed_id.begin(), composed_id.end()).size() == K_merged);
  // the step, on the cached stages
  CHECK(pd.compose_parts(boost::dummy_property_map(), switches(&Variant::use_pieces, false)) == K_merged);
  CHECK(pd.parts() == merged);
  CHECK(pd.part_primitives().size() == K_merged);
  REQUIRE(pd.part_to_primitive().size() == K_merged);
  for(std::size_t k = 0; k < K_function; ++k) CHECK(pd.part_to_primitive()[composed_id[k]] == part_to_primitive[k]);
}

TEST_CASE("decompose() with every default given explicitly gives the default parts", "[decompose][defaults][data]")
{
  namespace D = PD::defaults;
  Mesh m;
  test_shapes::read_shipped_shape("dumbbell", m);
  std::vector<std::size_t> a(num_faces(m)), b(num_faces(m));
  std::vector<PD::Superquadric<K> > pa, pb;
  const std::size_t na =
      PD::decompose(m, CGAL::make_property_map(a), PDP::primitive_output_iterator(std::back_inserter(pa)));
  const std::size_t nb = PD::decompose(
      m, CGAL::make_property_map(b),
      PDP::combine(
          CGAL::parameters::vertex_point_map(get(CGAL::vertex_point, m))
              .face_index_map(get(CGAL::face_index, m))
              .geom_traits(K())
              .number_of_points_per_face(D::number_of_points_per_face)
              .verbose(false),
          PDP::primitive_output_iterator(std::back_inserter(pb)),
          PDP::voxel_resolutions(D::voxel_resolutions), PDP::number_of_neighbors(D::number_of_neighbors),
          PDP::curvature_percentile(D::curvature_percentile), PDP::cue_weights(D::cue_weights),
          PDP::freeze_ratio(D::freeze_ratio), PDP::normalization_margin(D::normalization_margin), PDP::grid_resolution(D::grid_resolution),
          PDP::tsdf_truncation(D::tsdf_truncation),
          PDP::tsdf_sign_method(PD::Tsdf_sign_method::AUTOMATIC), PDP::flow_zone_tolerance(D::flow_zone_tolerance),
          PDP::trust_region_scales(D::trust_region_scales), PDP::body_seed_threshold(D::body_seed_threshold),
          PDP::minimum_body_volume(D::minimum_body_volume), PDP::minimum_surface_volume(D::minimum_surface_volume),
          PDP::exterior_penalty(D::exterior_penalty), PDP::coverage_target(D::coverage_target),
          PDP::roi_radius(D::roi_radius), PDP::method_variant(PD::Method_variant()),
          PDP::maximum_number_of_primitives(D::maximum_number_of_primitives),
          PDP::fitting_resolution_cap(D::fitting_resolution_cap),
          PDP::maximum_solver_evaluations(D::maximum_solver_evaluations),
          PDP::maximum_rejections_in_a_row(D::maximum_rejections_in_a_row),
          PDP::dihedral_percentile(D::dihedral_percentile), PDP::smoothing_iterations(D::smoothing_iterations),
          PDP::minimum_patch_size(D::minimum_patch_size), PDP::patch_split_size(D::patch_split_size),
          PDP::vote_temperature(D::vote_temperature), PDP::crease_angle(D::crease_angle),
          PDP::minimum_part_area(D::minimum_part_area), PDP::boundary_smoothness(D::boundary_smoothness),
          PDP::minimum_merge_iou(D::minimum_merge_iou),
          PDP::maximum_merge_cost(D::maximum_merge_cost)));
  CHECK(na == 3u); // two balls and a bar
  CHECK(nb == na);
  CHECK(b == a);
  check_same_primitives(pb, pa);
}

TEST_CASE("decompose() takes values of other types as the pipeline's and refuses what they cannot hold",
          "[decompose][defaults][data]")
{
  Mesh m;
  test_shapes::read_shipped_shape("dumbbell", m);
  const auto parts = [&](const auto& np) {
    std::vector<std::size_t> labels(num_faces(m));
    PD::decompose(m, CGAL::make_property_map(labels), np);
    return labels;
  };
  const std::vector<std::size_t> reference = parts(PDP::freeze_ratio(PD::defaults::freeze_ratio));
  // other arithmetic and range types of the same values give the same parts
  CHECK(parts(PDP::voxel_resolutions(std::array<long, 3>{{16, 32, 64}})) == reference);
  CHECK(parts(PDP::cue_weights(std::vector<float>{1.f, 1.f, 1.f, 0.f})) == reference);
  CHECK(parts(PDP::combine(PDP::grid_resolution(128.), PDP::smoothing_iterations(1))) == reference);
  CHECK(parts(PDP::freeze_ratio(0.15f)) == parts(PDP::freeze_ratio(double(0.15f))));
  std::vector<std::size_t> two(num_faces(m));
  CHECK(PD::decompose(m, CGAL::make_property_map(two), PDP::number_of_parts(2)) == 2u);
  // a value the parameter's type cannot hold is out of its range, not wrapped or truncated
  CHECK(error_of([&] { parts(PDP::number_of_parts(-1)); }) == PD::Input_error::INVALID_PARAMETER);
  CHECK(error_of([&] { parts(CGAL::parameters::number_of_points_per_face(36.5)); }) ==
        PD::Input_error::INVALID_PARAMETER);
  CHECK(error_of([&] { parts(PDP::voxel_resolutions(std::vector<double>{16., 32.5})); }) ==
        PD::Input_error::INVALID_PARAMETER);
  CHECK(error_of([&] { parts(PDP::cue_weights(std::vector<double>{1., 1.})); }) == PD::Input_error::INVALID_PARAMETER);
}

TEST_CASE("a stage given another normalization than the decomposer's is refused", "[decompose]")
{
  const Mesh m = test_shapes::make_box(Point(0, 0, 0), Point(1, 2, 3), 2);
  PD::Part_decomposer<Mesh> pd(m);
  const PD::Normalization other({{0., 0., 0.}}, 2. * pd.normalization().scale());
  CHECK(error_of([&] { pd.compute_prior(PDP::normalization(other)); }) == PD::Input_error::INVALID_PARAMETER);
  CHECK(error_of([&] { pd.compute_distance_field(PDP::normalization_margin(0.1)); }) ==
        PD::Input_error::INVALID_PARAMETER);
  CHECK(error_of([&] { pd.over_segment(PDP::normalization(other)); }) == PD::Input_error::INVALID_PARAMETER);
  // the decomposer's own frame is accepted
  CHECK(pd.compute_prior(PDP::normalization(pd.normalization())).normalization.scale() == pd.normalization().scale());
  std::vector<std::size_t> part(num_faces(m));
  CHECK(error_of([&] { PD::decompose(m, CGAL::make_property_map(part), PDP::normalization(other)); }) ==
        PD::Input_error::INVALID_PARAMETER);
}

TEST_CASE("the whole decomposition recovers the true parts of the shipped shapes", "[decompose][data]")
{
  // Unions of primitives (examples/Part_decomposition/generate_example_shapes): the .seg files
  // hold the primitive each face came from. A table (top and 4 legs), a four-legged animal
  // (body, head, legs, tail) and a dumbbell (two balls and a bar).
  const std::map<std::string, double> minimum_miou = {{"table", 0.85}, {"animal", 0.8}, {"dumbbell", 0.9}};
  for(const auto& e : minimum_miou)
  {
    INFO(e.first);
    Mesh m;
    const std::vector<std::size_t> truth = test_shapes::read_shipped_shape(e.first, m);

    std::vector<std::size_t> part(num_faces(m), std::size_t(-1));
    std::vector<PD::Superquadric<K> > primitives;
    const std::size_t K_parts = PD::decompose(
        m, CGAL::make_property_map(part),
        PD::parameters::primitive_output_iterator(std::back_inserter(primitives)));
    REQUIRE(primitives.size() == K_parts);
    for(std::size_t p : part) REQUIRE(p < K_parts);

    const PD::Segmentation_scores s =
        PD::evaluate_segmentation(m, CGAL::make_property_map(truth), CGAL::make_property_map(part));
    const std::size_t true_parts = std::set<std::size_t>(truth.begin(), truth.end()).size();
    INFO(e.first << ": parts " << K_parts << " (true " << true_parts << "), mIoU " << s.mean_iou << ", RI "
                  << s.rand_index << ", VoI " << s.variation_of_information);
    CHECK(s.mean_iou >= e.second);
    CHECK(K_parts >= true_parts - 1);
    // the region of interest of a seed is shorter than a table leg: legs may come in pieces
    CHECK(K_parts <= 3 * true_parts);
  }
}

// ------------------------------------------------------------------------------------------
// Pieces and creases

namespace {

// Adds the quad (a, b, c, d), split along a-c, oriented so that its normal points along `out`.
void add_quad(test_shapes::Soup& s, const Point& a, const Point& b, const Point& c, const Point& d,
              const test_shapes::Vector& out)
{
  if(CGAL::cross_product(b - a, c - a) * out > 0)
  {
    s.triangle(a, b, c);
    s.triangle(a, c, d);
  }
  else
  {
    s.triangle(a, c, b);
    s.triangle(a, d, c);
  }
}

// Adds the unit squares of the axis-aligned rectangle [lo, hi] (flat along `axis`) whose lower
// corner is not `skip`, oriented along `out`.
void add_grid(test_shapes::Soup& s, int axis, const std::array<int, 3>& lo, const std::array<int, 3>& hi,
              const test_shapes::Vector& out, const std::array<int, 3>& skip = {{-9, -9, -9}})
{
  const int u = (axis + 1) % 3, w = (axis + 2) % 3;
  for(int i = lo[u]; i < hi[u]; ++i)
    for(int j = lo[w]; j < hi[w]; ++j)
    {
      std::array<int, 3> c = lo;
      c[u] = i;
      c[w] = j;
      if(c == skip) continue;
      auto P = [&](int di, int dj) {
        std::array<double, 3> q = {{double(c[0]), double(c[1]), double(c[2])}};
        q[u] += di;
        q[w] += dj;
        return Point(q[0], q[1], q[2]);
      };
      add_quad(s, P(0, 0), P(1, 0), P(1, 1), P(0, 1), out);
    }
}

// One closed piece: the box [0,3]^2 x [0,1] with the box [1,2]^2 x [1,2] standing on it, the two
// meeting along a loop of concave 90-degree creases. Faces of the small box come last.
Mesh make_box_on_box(std::size_t& first_small_face)
{
  typedef test_shapes::Vector V;
  test_shapes::Soup s;
  add_grid(s, 2, {{0, 0, 0}}, {{3, 3, 0}}, V(0, 0, -1));
  add_grid(s, 2, {{0, 0, 1}}, {{3, 3, 1}}, V(0, 0, 1), {{1, 1, 1}});
  add_grid(s, 0, {{0, 0, 0}}, {{0, 3, 1}}, V(-1, 0, 0));
  add_grid(s, 0, {{3, 0, 0}}, {{3, 3, 1}}, V(1, 0, 0));
  add_grid(s, 1, {{0, 0, 0}}, {{3, 0, 1}}, V(0, -1, 0));
  add_grid(s, 1, {{0, 3, 0}}, {{3, 3, 1}}, V(0, 1, 0));
  first_small_face = s.triangles.size();
  add_grid(s, 2, {{1, 1, 2}}, {{2, 2, 2}}, V(0, 0, 1));
  add_grid(s, 0, {{1, 1, 1}}, {{1, 2, 2}}, V(-1, 0, 0));
  add_grid(s, 0, {{2, 1, 1}}, {{2, 2, 2}}, V(1, 0, 0));
  add_grid(s, 1, {{1, 1, 1}}, {{2, 1, 2}}, V(0, -1, 0));
  add_grid(s, 1, {{1, 2, 1}}, {{2, 2, 2}}, V(0, 1, 0));
  return s.mesh();
}

// An open box (no lid) [0,1]^3, its faces pointing out of the box or into it.
Mesh make_open_box(bool inward)
{
  typedef test_shapes::Vector V;
  const double f = inward ? -1. : 1.;
  test_shapes::Soup s;
  add_grid(s, 2, {{0, 0, 0}}, {{1, 1, 0}}, V(0, 0, -f));
  add_grid(s, 0, {{0, 0, 0}}, {{0, 1, 1}}, V(-f, 0, 0));
  add_grid(s, 0, {{1, 0, 0}}, {{1, 1, 1}}, V(f, 0, 0));
  add_grid(s, 1, {{0, 0, 0}}, {{1, 0, 1}}, V(0, -f, 0));
  add_grid(s, 1, {{0, 1, 0}}, {{1, 1, 1}}, V(0, f, 0));
  return s.mesh();
}

// An assembly of four separate pieces: three closed boxes in a row, apart from each other, and a
// plate of two large triangles under them. Returns the piece of each face.
Mesh make_assembly(std::vector<std::size_t>& truth)
{
  Mesh m;
  for(int b = 0; b < 3; ++b)
  {
    test_shapes::append(m, test_shapes::make_box(Point(3. * b, 0, 0.5), Point(3. * b + 2., 1., 0.8 + 0.1 * b), 4));
    truth.resize(num_faces(m), std::size_t(b));
  }
  test_shapes::Soup plate;
  add_quad(plate, Point(-1, -1, 0), Point(9, -1, 0), Point(9, 4, 0), Point(-1, 4, 0), test_shapes::Vector(0, 0, 1));
  test_shapes::append(m, plate.mesh());
  truth.resize(num_faces(m), 3);
  return m;
}

std::size_t number_of_labels(const std::vector<std::size_t>& label)
{
  return std::set<std::size_t>(label.begin(), label.end()).size();
}

// The part holding most faces of each plate of an L-bracket (`plate`: 0 or 1 per face); checks
// that it holds at least 90% of them.
std::array<std::size_t, 2> plate_parts(const Mesh& m, const std::vector<int>& plate, const std::vector<std::size_t>& part)
{
  std::array<std::map<std::size_t, std::size_t>, 2> count;
  std::array<std::size_t, 2> total = {{0, 0}};
  for(face_descriptor f : faces(m))
  {
    ++count[std::size_t(plate[std::size_t(f)])][part[std::size_t(f)]];
    ++total[std::size_t(plate[std::size_t(f)])];
  }
  std::array<std::size_t, 2> major;
  for(std::size_t p = 0; p < 2; ++p)
  {
    major[p] = count[p].begin()->first;
    for(const auto& c : count[p])
      if(c.second > count[p][major[p]]) major[p] = c.first;
    CHECK(double(count[p][major[p]]) >= 0.9 * double(total[p]));
  }
  return major;
}

} // namespace

// [!mayfail]: on the adaptive grid the fit leaves plate B's corner unclaimed, plate A's part takes
// three rows of B's faces and the sheet merge joins all parts: 1 part (2 with adaptive_grid(false)).
TEST_CASE("an L-bracket of plates thinner than two voxels gives two parts, each with a thin superquadric",
          "[decompose][thin][!mayfail]")
{
  // Plates 0.025 thick on a bracket 1 long: under two voxels (0.031) of the 64^3 grid.
  const double la = 1., lb = 0.7, t = 0.025, w = 0.4;
  std::vector<int> plate;
  Mesh m = test_shapes::make_l_bracket(la, lb, t, w, 0.02, &plate);
  std::vector<std::size_t> part(num_faces(m));
  std::vector<PD::Superquadric<K> > primitives;
  const std::size_t n = PD::decompose(m, CGAL::make_property_map(part),
                                      PDP::primitive_output_iterator(std::back_inserter(primitives)));
  REQUIRE(n == 2);
  // each plate is (almost all) one part, the two parts differ
  const std::array<std::size_t, 2> major = plate_parts(m, plate, part);
  REQUIRE(major[0] != major[1]);
  // the superquadric of each plate's part is a thin solid on the plate: its centre within three
  // voxels of the 64^3 grid (0.047) of the plate's centre (the cut may take the corner and two or
  // three voxels of the other plate's outer faces, which the box then spans), flat: its smallest
  // semi-axis under a quarter of its largest
  const std::array<Point, 2> centre = {{Point(la / 2, t / 2, w / 2), Point(t / 2, lb / 2, w / 2)}};
  for(std::size_t p = 0; p < 2; ++p)
  {
    const PD::Superquadric<K>& q = primitives[major[p]];
    INFO("plate " << p << ": centre " << q.center() << ", semi-axes " << q.scales()[0] << " " << q.scales()[1] << " "
                  << q.scales()[2]);
    CHECK(std::sqrt(CGAL::squared_distance(q.center(), centre[p])) < 3. / 64.);
    std::array<double, 3> a = q.scales();
    std::sort(a.begin(), a.end());
    CHECK(a[0] < 0.25 * a[2]);
  }
}

// [!mayfail]: as above, the seam lies three rows off the crease on the adaptive grid.
TEST_CASE("the thin-sheet merge keeps a fold apart when its seam lies a row of faces off the crease",
          "[decompose][thin][!mayfail]")
{
  // Fitted at 64, the inner corner of the L-bracket above gets a strip primitive of its own and one
  // plate's part takes a row of the other plate's faces: the seam between the plates runs on a
  // flat face next to the crease. Counting only the edges on the seam, the sheet merge joined them.
  std::vector<int> plate;
  Mesh m = test_shapes::make_l_bracket(1., 0.7, 0.025, 0.4, 0.02, &plate);
  std::vector<std::size_t> part(num_faces(m));
  const std::size_t n = PD::decompose(m, CGAL::make_property_map(part), PDP::fitting_resolution_cap(64));
  REQUIRE(n == 2);
  const std::array<std::size_t, 2> major = plate_parts(m, plate, part);
  CHECK(major[0] != major[1]);
}

TEST_CASE("pieces, their closedness and the regions between concave creases", "[pieces]")
{
  SECTION("two boxes standing on each other as one closed piece: two regions")
  {
    std::size_t first_small = 0;
    const Mesh m = make_box_on_box(first_small);
    const PD::Piece_segmentation s = PD::segment_pieces(m);
    CHECK(s.number_of_pieces == 1);
    CHECK(s.closed == std::vector<std::uint8_t>{1});
    REQUIRE(s.number_of_regions == 2);
    for(std::size_t i = 0; i < num_faces(m); ++i) CHECK(s.region[i] == (i < first_small ? 0u : 1u));
    CHECK(s.area == Approx(9 + 8 + 12 + 1 + 4));
    // a crease angle above 90 degrees sees no crease
    CHECK(PD::segment_pieces(m, PDP::crease_angle(91.)).number_of_regions == 1);
  }
  SECTION("an open box is one region whichever way its faces point")
  {
    for(bool inward : {false, true})
    {
      CAPTURE(inward);
      const Mesh m = make_open_box(inward);
      const PD::Piece_segmentation s = PD::segment_pieces(m);
      CHECK(s.number_of_pieces == 1);
      CHECK(s.closed == std::vector<std::uint8_t>{0});
      CHECK(s.orientation == std::vector<int>{inward ? -1 : 1});
      CHECK(s.number_of_regions == 1);
    }
  }
  SECTION("separate pieces")
  {
    std::vector<std::size_t> truth;
    const Mesh m = make_assembly(truth);
    const PD::Piece_segmentation s = PD::segment_pieces(m);
    CHECK(s.number_of_pieces == 4);
    CHECK(s.piece == truth);
    CHECK(s.region == truth);
    CHECK(s.closed == std::vector<std::uint8_t>{1, 1, 1, 0});
  }
  CHECK(error_of([] { PD::segment_pieces(make_open_box(false), PDP::crease_angle(0.)); }) ==
        PD::Input_error::INVALID_PARAMETER);
}

TEST_CASE("an assembly of convex pieces is decomposed into its pieces, each with its primitive", "[pieces][decompose]")
{
  std::vector<std::size_t> truth;
  const Mesh m = make_assembly(truth);
  std::vector<std::size_t> part(num_faces(m));
  std::vector<PD::Superquadric<K> > primitives;
  PD::Stage_timings timings;
  const std::size_t K_parts =
      PD::decompose(m, CGAL::make_property_map(part),
                    PDP::combine(PDP::primitive_output_iterator(std::back_inserter(primitives)),
                                 PDP::stage_timings(&timings)));
  CHECK(K_parts == 4);
  CHECK(part == truth); // the two triangles of the plate in one part
  // convex pieces need no volumetric stage
  CHECK(timings.prior == 0.);
  CHECK(timings.fitting == 0.);
  REQUIRE(primitives.size() == 4);
  for(std::size_t b = 0; b < 3; ++b)
  {
    CAPTURE(b);
    // the box-like superquadric of the piece's principal-axis bounding box: its half extents
    std::array<double, 3> sc = primitives[b].scales();
    std::sort(sc.begin(), sc.end());
    CHECK(sc[0] == Approx(0.15 + 0.05 * double(b)));
    CHECK(sc[1] == Approx(0.5));
    CHECK(sc[2] == Approx(1.));
    CHECK(primitives[b].center().x() == Approx(3. * double(b) + 1.));
  }
  // the plate: a flat primitive of its extent
  std::array<double, 3> plate = primitives[3].scales();
  std::sort(plate.begin(), plate.end());
  CHECK(plate[0] < 1e-3 * plate[2]);
  CHECK(plate[1] == Approx(2.5));
  CHECK(plate[2] == Approx(5.));
  // without the evidence of pieces the volumetric stages run
  std::vector<std::size_t> volumetric(num_faces(m));
  PD::decompose(m, CGAL::make_property_map(volumetric), PDP::combine(switches(&Variant::use_pieces, false), PDP::stage_timings(&timings)));
  CHECK(timings.prior > 0.);
  CHECK(error_of([&] { PD::decompose(m, CGAL::make_property_map(part), PDP::minimum_part_area(2.)); }) ==
        PD::Input_error::INVALID_PARAMETER);
}

TEST_CASE("a closed non-convex piece is split by the volumetric stages along its concave creases", "[pieces][decompose]")
{
  std::size_t first_small = 0;
  const Mesh m = make_box_on_box(first_small);
  std::vector<std::size_t> truth(num_faces(m), 0);
  for(std::size_t i = first_small; i < truth.size(); ++i) truth[i] = 1;
  std::vector<std::size_t> reference;
  for(std::size_t threads : {1, 2, 3})
  {
    CAPTURE(threads);
#ifdef CGAL_LINKED_WITH_TBB
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
#endif
    std::vector<std::size_t> part(num_faces(m));
    PD::Stage_timings timings;
    const std::size_t K_parts = PD::decompose(m, CGAL::make_property_map(part), PDP::stage_timings(&timings));
    CHECK(timings.fitting > 0.);
    // no part crosses the crease loop, and the small box is mostly one part
    CHECK(K_parts >= 2);
    for(std::size_t i = 0; i < first_small; ++i)
      for(std::size_t j = first_small; j < truth.size(); ++j)
        if(part[i] == part[j]) FAIL("a part crosses the concave crease loop");
    const PD::Segmentation_scores sc =
        PD::evaluate_segmentation(m, CGAL::make_property_map(truth), CGAL::make_property_map(part));
    CHECK(sc.mean_iou > 0.6);
    if(reference.empty()) reference = part;
    CHECK(part == reference);
  }
}

TEST_CASE("a part below minimum_part_area joins a neighbour of its piece", "[pieces][decompose]")
{
  std::size_t first_small = 0;
  const Mesh m = make_box_on_box(first_small);
  // the small box has 5 of 34 area units: with a minimum of 0.2 it cannot stand alone
  std::vector<std::size_t> part(num_faces(m));
  const std::size_t K_parts = PD::decompose(m, CGAL::make_property_map(part), PDP::minimum_part_area(0.2));
  std::vector<bool> has_big_box_face(K_parts, false);
  for(std::size_t i = 0; i < first_small; ++i) has_big_box_face[part[i]] = true;
  for(std::size_t k = 0; k < K_parts; ++k) CHECK(has_big_box_face[k]);
}

TEST_CASE("the stretches of one volumetric part with a concave boundary are parts, a stray claim is not",
          "[pieces][compose]")
{
  // a slab of 8 x 4 x 2 unit cubes with two pegs on top, 3 and 2 cubes high
  std::vector<std::array<int, 3> > cubes;
  for(int x = 0; x < 8; ++x)
    for(int y = 0; y < 4; ++y)
      for(int z = 0; z < 2; ++z) cubes.push_back({{x, y, z}});
  for(int x0 : {1, 5})
    for(int x = x0; x < x0 + 2; ++x)
      for(int y = 1; y < 3; ++y)
        for(int z = 2; z < (x0 == 1 ? 5 : 4); ++z) cubes.push_back({{x, y, z}});
  const Mesh m = test_shapes::make_union_of_cubes(cubes);
  // one volumetric part claims both pegs and a flat patch of the bottom, another the slab
  enum Face_kind { SLAB, PEG_A, PEG_B, PATCH };
  std::vector<Face_kind> kind;
  PD::Volumetric_parts parts;
  for(face_descriptor f : faces(m))
  {
    Point c[3];
    int n = 0;
    for(auto v : vertices_around_face(halfedge(f, m), m)) c[n++] = m.point(v);
    const Point g = CGAL::centroid(c[0], c[1], c[2]);
    kind.push_back(g.z() > 2. ? (g.x() < 4. ? PEG_A : PEG_B)
                   : g.z() == 0. && g.x() > 3. && g.x() < 5. && g.y() > 1. && g.y() < 3. ? PATCH : SLAB);
    parts.parts.push_back(kind.back() == SLAB ? 0 : 1);
  }
  parts.part_to_primitive.assign(2, PD::no_primitive);
  // concave creases do not cut the piece into regions here: only the volumetric parts divide it
  const auto np = PDP::combine(PDP::crease_angle(100.), PDP::minimum_part_area(0.));
  const PD::Piece_segmentation pieces = PD::segment_pieces(m, np);
  REQUIRE(pieces.number_of_regions == 1);
  const PD::Composed_parts<K> c =
    PD::compose_parts(m, pieces, std::vector<std::uint8_t>(1, 1), parts, PD::Superquadric_fitting_result<K>(), np);
  // the pegs end at concave roots: a part each; the patch, bounded by flat edges, stays with peg A
  // (the larger stretch of its volumetric part)
  CHECK(c.number_of_parts() == 3);
  std::map<Face_kind, std::set<std::size_t> > part_of;
  for(std::size_t i = 0; i < kind.size(); ++i) part_of[kind[i]].insert(c.parts[i]);
  for(const auto& e : part_of) CHECK(e.second.size() == 1);
  CHECK(part_of[PATCH] == part_of[PEG_A]);
  CHECK(part_of[PEG_A] != part_of[PEG_B]);
  CHECK(part_of[SLAB] != part_of[PEG_A]);
  CHECK(part_of[SLAB] != part_of[PEG_B]);
}

namespace {

// Three closed boxes in a row along x, touching: two of equal section (one box explains their
// union) and a small one at the end given by `small_first`. Returns the box of each face.
Mesh make_three_boxes(bool small_first, std::vector<std::size_t>& box)
{
  Mesh m;
  const double x0 = small_first ? 0.4 : 0.;
  std::vector<std::pair<Point, Point> > boxes = {{Point(x0, 0, 0), Point(x0 + 1, 1, 1)},
                                                 {Point(x0 + 1, 0, 0), Point(x0 + 2, 1, 1)}};
  const std::pair<Point, Point> small =
    small_first ? std::make_pair(Point(0, 0.3, 0.3), Point(0.4, 0.7, 0.7)) : std::make_pair(Point(2, 0.3, 0.3), Point(2.4, 0.7, 0.7));
  boxes.insert(small_first ? boxes.begin() : boxes.end(), small);
  for(std::size_t b = 0; b < 3; ++b)
  {
    // different grids: no two boxes have a face with the same corners (that would weld them)
    test_shapes::append(m, test_shapes::make_box(boxes[b].first, boxes[b].second, int(b) + 2));
    box.resize(num_faces(m), b);
  }
  return m;
}

// Whether every part of `fine` lies in one part of `coarse`.
bool refines(const std::vector<std::size_t>& fine, const std::vector<std::size_t>& coarse)
{
  std::map<std::size_t, std::size_t> parent;
  for(std::size_t i = 0; i < fine.size(); ++i)
    if(parent.emplace(fine[i], coarse[i]).first->second != coarse[i]) return false;
  return true;
}

} // namespace

TEST_CASE("three boxes in a row: two parts join the two boxes one box explains", "[hierarchy]")
{
  for(bool small_first : {false, true})
  {
    CAPTURE(small_first);
    std::vector<std::size_t> box;
    const Mesh m = make_three_boxes(small_first, box);
    const std::size_t small = small_first ? 0 : 2;
    for(std::size_t k : {1, 2, 3})
    {
      CAPTURE(k);
      std::vector<std::size_t> part(num_faces(m));
      std::vector<PD::Superquadric<K> > primitives;
      CHECK(PD::decompose(m, CGAL::make_property_map(part),
                          PDP::combine(PDP::number_of_parts(k),
                                       PDP::primitive_output_iterator(std::back_inserter(primitives)))) == k);
      CHECK(number_of_labels(part) == k);
      REQUIRE(primitives.size() == k);
      for(std::size_t i = 0; i < part.size(); ++i)
        for(std::size_t j = 0; j < part.size(); ++j)
        {
          const bool together = part[i] == part[j];
          if(k == 3) CHECK(together == (box[i] == box[j]));
          if(k == 2) CHECK(together == ((box[i] == small) == (box[j] == small)));
        }
      if(k == 2)
      {
        // the two big boxes are one box-like superquadric of half extents 1, 0.5, 0.5
        const PD::Superquadric<K>& q = primitives[part[small == 0 ? num_faces(m) - 1 : 0]];
        std::array<double, 3> sc = q.scales();
        std::sort(sc.begin(), sc.end());
        CHECK(sc[0] == Approx(0.5));
        CHECK(sc[2] == Approx(1.));
      }
    }
    // the free function on the boxes as leaves: the same first merge
    const PD::Part_hierarchy<K> h = PD::build_part_hierarchy(m, CGAL::make_property_map(box));
    REQUIRE(h.number_of_leaves() == 3);
    REQUIRE(h.nodes.size() == 5);
    const std::array<std::size_t, 2> first = h.nodes[3].children;
    CHECK(std::set<std::size_t>(first.begin(), first.end()) ==
          (small_first ? std::set<std::size_t>{1, 2} : std::set<std::size_t>{0, 1}));
    CHECK(h.nodes[3].kind == PD::Merge_kind::CONTACT);
    CHECK(h.nodes[4].parent == PD::Part_hierarchy<K>::Node::no_node);
    CHECK(h.nodes[4].merge_cost > h.nodes[3].merge_cost);
  }
}

TEST_CASE("maximum_merge_cost: the two boxes one box explains are one part by default", "[hierarchy][decompose]")
{
  for(bool small_first : {false, true})
  {
    CAPTURE(small_first);
    std::vector<std::size_t> box;
    const Mesh m = make_three_boxes(small_first, box);
    const std::size_t small = small_first ? 0 : 2;
    // without the merges: one part per box (three pieces)
    std::vector<std::size_t> assigned(num_faces(m)), part(num_faces(m));
    CHECK(PD::decompose(m, CGAL::make_property_map(assigned), PDP::maximum_merge_cost(0.)) == 3);
    for(std::size_t i = 0; i < assigned.size(); ++i)
      for(std::size_t j = 0; j < assigned.size(); ++j)
        if((assigned[i] == assigned[j]) != (box[i] == box[j])) FAIL("faces " << i << " and " << j);
    // by default the two big boxes merge (their union is a box: cost 0), the small one stays
    std::vector<PD::Superquadric<K> > primitives;
    PD::Part_hierarchy<K> h;
    CHECK(PD::decompose(m, CGAL::make_property_map(part),
                        PDP::combine(PDP::part_hierarchy(&h),
                                     PDP::primitive_output_iterator(std::back_inserter(primitives)))) == 2);
    CHECK(h.default_number_of_parts == 2);
    CHECK(h.level_below_cost(3, 0.) == 3);
    CHECK(h.level_below_cost(3, PD::defaults::maximum_merge_cost) == 2);
    CHECK(h.level_below_cost(3, 1e9) == 1);
    CHECK(h.labels(2) == part);
    REQUIRE(primitives.size() == 2);
    for(std::size_t i = 0; i < part.size(); ++i)
      if((part[i] == part[small == 0 ? 0 : num_faces(m) - 1]) != (box[i] == small)) FAIL("face " << i);
    std::array<double, 3> sc = primitives[part[small == 0 ? num_faces(m) - 1 : 0]].scales();
    std::sort(sc.begin(), sc.end());
    CHECK(sc[0] == Approx(0.5));
    CHECK(sc[2] == Approx(1.));
    CHECK(error_of([&] { PD::decompose(m, CGAL::make_property_map(part), PDP::maximum_merge_cost(-1.)); }) ==
          PD::Input_error::INVALID_PARAMETER);
  }
}

TEST_CASE("the levels of the hierarchy have exact counts, are nested and hold the default parts", "[hierarchy][decompose][data]")
{
  Mesh m;
  test_shapes::read_shipped_shape("dumbbell", m);
  std::vector<std::size_t> reference_leaf;
  std::vector<std::array<std::size_t, 2> > reference_children;
  std::vector<double> reference_cost;
  for(std::size_t threads : {1, 2, 3})
  {
    CAPTURE(threads);
#ifdef CGAL_LINKED_WITH_TBB
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
#endif
    std::vector<std::size_t> part(num_faces(m));
    PD::Part_hierarchy<K> h;
    PD::Stage_timings timings;
    const std::size_t K_default =
      PD::decompose(m, CGAL::make_property_map(part), PDP::combine(PDP::part_hierarchy(&h), PDP::stage_timings(&timings)));
    CHECK(timings.hierarchy > 0.);
    REQUIRE(h.default_number_of_parts == K_default);
    REQUIRE(h.number_of_leaves() > K_default);
    REQUIRE(h.nodes.size() == 2 * h.number_of_leaves() - 1);
    CHECK(h.labels(K_default) == part); // the default parts are a level
    std::vector<std::size_t> finer = h.labels(h.number_of_leaves());
    CHECK(finer == h.leaf);
    for(std::size_t k = h.number_of_leaves() - 1; k >= 1; --k)
    {
      const std::vector<std::size_t> level = h.labels(k);
      if(number_of_labels(level) != k || !refines(finer, level)) FAIL("level " << k << " is not a k-partition coarser than level " << k + 1);
      finer = level;
    }
    if(threads == 1)
    {
      reference_leaf = h.leaf;
      for(const auto& n : h.nodes) { reference_children.push_back(n.children); reference_cost.push_back(n.merge_cost); }
    }
    else
    {
      CHECK(h.leaf == reference_leaf);
      for(std::size_t n = 0; n < h.nodes.size(); ++n)
        if(h.nodes[n].children != reference_children[n] || h.nodes[n].merge_cost != reference_cost[n])
          FAIL("node " << n << " differs from the one-thread tree");
    }
    // number_of_parts: exact, clamped above the leaves, refused at 0
    std::vector<std::size_t> cut(num_faces(m));
    CHECK(PD::decompose(m, CGAL::make_property_map(cut), PDP::number_of_parts(std::size_t(3))) == 3);
    CHECK(cut == h.labels(3));
    CHECK(PD::decompose(m, CGAL::make_property_map(cut), PDP::number_of_parts(std::size_t(1) << 40)) == h.number_of_leaves());
    CHECK(cut == h.leaf);
    CHECK(error_of([&] { PD::decompose(m, CGAL::make_property_map(cut), PDP::number_of_parts(std::size_t(0))); }) ==
          PD::Input_error::INVALID_PARAMETER);
  }
}

TEST_CASE("residual patches are parts of their own, without a fitted primitive", "[residual][decompose][data]")
{
  Mesh m;
  test_shapes::read_shipped_shape("animal", m);
  PD::Part_decomposer<Mesh> d(m);
  std::vector<std::size_t> part(num_faces(m));
  const auto np = PDP::combine(switches(&Variant::keep_residual_patches, true), PDP::residual_tolerance(0.));
  d.segment_pieces(np);
  d.compute_prior(np);
  d.compute_distance_field(np);
  d.fit_primitives(np);
  d.over_segment(np);
  const std::size_t K_parts = d.compose_parts(CGAL::make_property_map(part), np);
  REQUIRE(d.residual_parts().size() == K_parts);
  // with a tolerance of 0 every Freeze-dominant patch is residual: some part is, and has no primitive
  std::size_t residual = 0;
  for(std::size_t k = 0; k < K_parts; ++k)
    if(d.residual_parts()[k])
    {
      ++residual;
      CHECK(d.part_to_primitive()[k] == PD::no_primitive);
    }
  CHECK(residual > 0);
  // off by default
  std::vector<std::size_t> plain(num_faces(m));
  d.compose_parts(CGAL::make_property_map(plain));
  CHECK(std::count(d.residual_parts().begin(), d.residual_parts().end(), 1) == 0);
  CHECK(error_of([&] { d.compose_parts(CGAL::make_property_map(plain), PDP::residual_tolerance(-1.)); }) ==
        PD::Input_error::INVALID_PARAMETER);
}

namespace {

// The part of `truth` of the face whose centroid is nearest to each leaf of depth `depth` of the
// grid of `tsdf`, counted per part.
std::map<std::size_t, std::size_t> parts_near_leaves(const Mesh& m, const std::vector<std::size_t>& truth,
                                                     const PD::Truncated_signed_distance_field& tsdf, int depth)
{
  std::vector<std::array<double, 3> > centroid;
  for(face_descriptor f : faces(m))
  {
    const auto h = halfedge(f, m);
    const Point c = CGAL::centroid(m.point(source(h, m)), m.point(target(h, m)), m.point(target(next(h, m), m)));
    centroid.push_back(tsdf.normalization.to_unit(c.x(), c.y(), c.z()));
  }
  std::map<std::size_t, std::size_t> count;
  for(std::size_t l = 0; l < tsdf.grid.number_of_leaves(); ++l)
  {
    if(tsdf.grid.depth(l) != depth) continue;
    const std::array<double, 3> c = tsdf.grid.center(l);
    double best = 1e30;
    std::size_t nearest = 0;
    for(std::size_t i = 0; i < centroid.size(); ++i)
    {
      const double d = (c[0] - centroid[i][0]) * (c[0] - centroid[i][0]) + (c[1] - centroid[i][1]) * (c[1] - centroid[i][1]) +
                       (c[2] - centroid[i][2]) * (c[2] - centroid[i][2]);
      if(d < best) best = d, nearest = i;
    }
    ++count[truth[nearest]];
  }
  return count;
}

} // namespace

TEST_CASE("the grid of the pipeline reaches 128 where the shape is thin, and its thin parts are parts",
          "[decompose][thin_parts][data]")
{
  // The finest leaves (128, grid_resolution) are where the surface faces its other side within
  // about four voxels of the 64^3 grid. The animal's tail (a capsule of diameter 0.06 on a shape
  // 1.5 long: 2.4 voxels) is thin, its body and head (more than 8 voxels across) are not; the
  // dumbbell's bar (diameter 0.2 on 2: 6 voxels) and balls are not.
  {
    Mesh m;
    const std::vector<std::size_t> truth = test_shapes::read_shipped_shape("animal", m);
    PD::Part_decomposer<Mesh> pd(m);
    const PD::Truncated_signed_distance_field& tsdf = pd.compute_distance_field();
    REQUIRE(tsdf.grid.finest_resolution() == PD::defaults::grid_resolution);
    const std::size_t finest = tsdf.grid.number_of_leaves_of_depth(7);
    REQUIRE(finest > 0);
    std::map<std::size_t, std::size_t> near = parts_near_leaves(m, truth, tsdf, 7);
    INFO("128 leaves: " << finest << ", near the body " << near[0] << ", head " << near[1] << ", tail " << near[6]);
    CHECK(near[6] > 0);                       // the tail
    CHECK(10 * (near[0] + near[1]) < finest); // body (0) and head (1)
    // fewer leaves than the dense grid, which the interior of the body does not need
    CHECK(tsdf.grid.number_of_leaves() < 64u * 64u * 64u / 8u);
  }
  {
    Mesh m;
    test_shapes::read_shipped_shape("dumbbell", m);
    PD::Part_decomposer<Mesh> pd(m);
    CHECK(pd.compute_distance_field().grid.number_of_leaves_of_depth(7) == 0);
  }
  // the former finer pass's known answers, now at the defaults: the table's parts are its true
  // parts (a leg at most losing its tip), the animal's seven parts are found, whatever the threads
  for(const std::pair<std::string, double>& e : {std::make_pair(std::string("table"), 0.95), std::make_pair(std::string("animal"), 0.9)})
  {
    CAPTURE(e.first);
    Mesh m;
    const std::vector<std::size_t> truth = test_shapes::read_shipped_shape(e.first, m);
    std::vector<std::size_t> part(num_faces(m)), part_sequential(num_faces(m));
    const std::size_t K_parts = PD::decompose(m, CGAL::make_property_map(part));
    CHECK(PD::decompose<CGAL::Sequential_tag>(m, CGAL::make_property_map(part_sequential)) == K_parts);
    CHECK(part_sequential == part);
    const double miou =
      PD::evaluate_segmentation(m, CGAL::make_property_map(truth), CGAL::make_property_map(part)).mean_iou;
    INFO(K_parts << " parts, mIoU " << miou);
    CHECK(miou >= e.second);
  }
}

TEST_CASE("told the default number of parts, decompose() gives the default parts, a level of its hierarchy",
          "[decompose][data]")
{
  Mesh m;
  const std::vector<std::size_t> truth = test_shapes::read_shipped_shape("animal", m);
  const std::size_t nf = num_faces(m);
  std::vector<std::size_t> plain(nf), part(nf), part_sequential(nf);
  std::vector<PD::Superquadric<K> > plain_primitives;
  PD::Part_hierarchy<K> h0, h;
  PD::decompose(m, CGAL::make_property_map(plain),
                PDP::combine(PDP::part_hierarchy(&h0), PDP::primitive_output_iterator(std::back_inserter(plain_primitives))));
  const std::size_t D = h0.default_number_of_parts;
  REQUIRE(D >= 2);

  // fewer parts than the default ones: the level of the hierarchy
  CHECK(PD::decompose(m, CGAL::make_property_map(part), PDP::number_of_parts(D - 1)) == D - 1);
  CHECK(part == h0.labels(D - 1));

  // the default number: the default parts, with their superquadrics
  std::vector<PD::Superquadric<K> > primitives;
  const std::size_t K_parts =
    PD::decompose(m, CGAL::make_property_map(part),
                  PDP::combine(PDP::number_of_parts(D), PDP::part_hierarchy(&h),
                               PDP::primitive_output_iterator(std::back_inserter(primitives))));
  CHECK(K_parts == D);
  CHECK(part == h.labels(K_parts));
  CHECK(part == plain);
  REQUIRE(primitives.size() == K_parts);
  check_same_primitives(primitives, plain_primitives);
  for(std::size_t k = 0; k < K_parts; ++k) CHECK(primitives[k].center() == h.primitives(K_parts)[k].center());
  // the animal's seven true parts, found
  const double miou =
    PD::evaluate_segmentation(m, CGAL::make_property_map(truth), CGAL::make_property_map(part)).mean_iou;
  INFO("told " << D << " parts: mIoU " << miou);
  CHECK(miou >= 0.9);
  CHECK(PD::decompose<CGAL::Sequential_tag>(m, CGAL::make_property_map(part_sequential),
                                            PDP::number_of_parts(D)) == K_parts);
  CHECK(part_sequential == part);
}

// ------------------------------------------------------------------------------------------
// Open and split meshes

namespace {

// A shipped shape's faces `kept` (indices in the order of faces(m)) as a mesh built by the reader,
// with their true parts in the order of its faces.
Mesh open_shape(const Mesh& closed, const std::vector<std::size_t>& truth, const std::vector<std::size_t>& kept,
                std::vector<std::size_t>& open_truth)
{
  std::vector<std::array<double, 3> > points;
  std::vector<std::array<std::size_t, 3> > triangles, kept_triangles;
  test_shapes::mesh_soup(closed, points, triangles);
  for(std::size_t i : kept) kept_triangles.push_back(triangles[i]);
  Mesh m;
  const PD::IO::Mesh_file_info info = PD::IO::triangle_mesh_from_polygon_soup(points, kept_triangles, m);
  open_truth.clear();
  for(std::size_t i : info.face_to_input) open_truth.push_back(truth[kept[i]]);
  return m;
}

struct Scored_parts
{
  std::size_t parts = 0;
  double miou = 0.;
};

Scored_parts decompose_and_score(const Mesh& m, const std::vector<std::size_t>& truth)
{
  std::vector<std::size_t> part(num_faces(m));
  Scored_parts s;
  s.parts = PD::decompose(m, CGAL::make_property_map(part));
  s.miou = PD::evaluate_segmentation(m, CGAL::make_property_map(truth), CGAL::make_property_map(part)).mean_iou;
  return s;
}

} // namespace

TEST_CASE("a shape with holes punched in it gets the parts of the closed shape", "[decompose][open][data]")
{
  // The dumbbell (two balls and a bar) and the animal (body, head, legs, tail), with 3 holes of 1%
  // and 6 holes of 0.8% of their area: the flood fill of the paper would enter through the holes and
  // leave one part; the winding number keeps the inside.
  for(const std::string name : {"dumbbell", "animal"})
  {
    Mesh closed;
    const std::vector<std::size_t> truth = test_shapes::read_shipped_shape(name, closed);
    const Scored_parts whole = decompose_and_score(closed, truth);
    for(const std::pair<int, double>& holes : {std::make_pair(3, 0.01), std::make_pair(6, 0.008)})
    {
      INFO(name << " with " << holes.first << " holes of " << holes.second << " of the area");
      std::vector<std::size_t> open_truth;
      const Mesh open = open_shape(closed, truth, test_shapes::faces_outside_holes(closed, holes.first, holes.second), open_truth);
      REQUIRE(!CGAL::is_closed(open));
      const Scored_parts s = decompose_and_score(open, open_truth);
      INFO("closed: " << whole.parts << " parts, mIoU " << whole.miou << "; open: " << s.parts << " parts, mIoU " << s.miou);
      CHECK(s.parts + 1 >= whole.parts);
      CHECK(s.parts <= whole.parts + 1);
      CHECK(s.miou >= whole.miou - 0.05);
    }
  }
}

TEST_CASE("a surface split into two meshes whose seam differs by float32 round-off is welded", "[decompose][open][io][data]")
{
  // The dumbbell cut by the plane x = 0.1 into two meshes; the second one stored in float32 in the
  // frame of a node transform (rotation, scale 3, translation) and brought back in double, as a
  // glTF reader does: the two copies of each seam vertex differ in their last bits.
  Mesh whole;
  const std::vector<std::size_t> truth = test_shapes::read_shipped_shape("dumbbell", whole);
  std::vector<std::array<double, 3> > points;
  std::vector<std::array<std::size_t, 3> > triangles;
  test_shapes::mesh_soup(whole, points, triangles);
  const double c = std::cos(0.7), s = std::sin(0.7), scale = 3.;
  const std::array<double, 3> shift = {{10., -4., 7.}};
  auto to_float = [](double x) { return double(float(x)); };
  auto round_trip = [&](const std::array<double, 3>& p) { // world -> float32 local -> world
    const std::array<double, 3> q = {{p[0] - shift[0], p[1] - shift[1], p[2] - shift[2]}};
    const std::array<double, 3> local = {{to_float((c * q[0] + s * q[1]) / scale), to_float((-s * q[0] + c * q[1]) / scale),
                                          to_float(q[2] / scale)}};
    const double a = to_float(scale * c), b = to_float(scale * s), z = to_float(scale);
    return std::array<double, 3>{{a * local[0] - b * local[1] + to_float(shift[0]),
                                  b * local[0] + a * local[1] + to_float(shift[1]), z * local[2] + to_float(shift[2])}};
  };
  std::vector<std::array<double, 3> > split_points;
  std::vector<std::array<std::size_t, 3> > split_triangles;
  std::vector<std::size_t> split_truth;
  for(int side = 0; side < 2; ++side)
  {
    std::vector<std::size_t> id(points.size(), std::size_t(-1));
    for(std::size_t t = 0; t < triangles.size(); ++t)
    {
      double x = 0.;
      for(std::size_t v : triangles[t]) x += points[v][0] / 3.;
      if((x < 0.1) != (side == 0)) continue;
      std::array<std::size_t, 3> tri;
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t v = triangles[t][std::size_t(k)];
        if(id[v] == std::size_t(-1))
        {
          id[v] = split_points.size();
          split_points.push_back(side == 0 ? std::array<double, 3>{{to_float(points[v][0]), to_float(points[v][1]), to_float(points[v][2])}}
                                           : round_trip(points[v]));
        }
        tri[std::size_t(k)] = id[v];
      }
      split_triangles.push_back(tri);
      split_truth.push_back(truth[t]);
    }
  }
  Mesh welded, apart;
  const PD::IO::Mesh_file_info info = PD::IO::triangle_mesh_from_polygon_soup(split_points, split_triangles, welded);
  const PD::IO::Mesh_file_info info_apart =
    PD::IO::triangle_mesh_from_polygon_soup(split_points, split_triangles, apart, PDP::weld_tolerance(0.));
  CHECK(info.number_of_welded_vertices > 10);
  CHECK(info_apart.number_of_welded_vertices == 0);
  CHECK(PD::segment_pieces(welded).number_of_pieces == 1);
  CHECK(PD::segment_pieces(apart).number_of_pieces == 2);

  std::vector<std::size_t> welded_truth;
  for(std::size_t i : info.face_to_input) welded_truth.push_back(split_truth[i]);
  const Scored_parts unsplit = decompose_and_score(whole, truth), split = decompose_and_score(welded, welded_truth);
  INFO("unsplit: " << unsplit.parts << " parts, mIoU " << unsplit.miou << "; split and welded: " << split.parts
                   << " parts, mIoU " << split.miou);
  CHECK(split.parts == unsplit.parts);
  CHECK(split.miou >= unsplit.miou - 0.02);
}

// [!mayfail]: on the adaptive grid 0.55 of the corrugated sheet's area separates inside from outside
// (0.44 on the dense grid), above the threshold of 0.5: it is taken for a volume.
TEST_CASE("whether a piece bounds a volume is decided by the distance field, not by closedness",
          "[decompose][open][!mayfail]")
{
  // A corrugated open sheet is not convex, so it may need the volumetric stages, until the distance
  // field shows that it bounds no volume (its dips hold a few voxels, the rest has the outside on
  // both sides); a dumbbell with holes bounds one.
  const Mesh wavy = test_shapes::make_wavy_sheet(24, 0.15);
  PD::Part_decomposer<Mesh> sheet_decomposer(wavy);
  sheet_decomposer.segment_pieces();
  CHECK(sheet_decomposer.needs_volumetric_stages());
  sheet_decomposer.compute_distance_field();
  CHECK_FALSE(sheet_decomposer.needs_volumetric_stages());

  // the shipped dumbbell with three holes of 2% of its area: it still bounds its volume
  Mesh closed;
  const std::vector<std::size_t> truth = test_shapes::read_shipped_shape("dumbbell", closed);
  std::vector<std::size_t> open_truth;
  const Mesh open = open_shape(closed, truth, test_shapes::faces_outside_holes(closed, 3, 0.02), open_truth);
  PD::Part_decomposer<Mesh> open_decomposer(open);
  REQUIRE_FALSE(open_decomposer.segment_pieces().closed[0]);
  CHECK(open_decomposer.needs_volumetric_stages());
  open_decomposer.compute_distance_field();
  CHECK(open_decomposer.needs_volumetric_stages());
}

namespace {

// Two L-brackets apart, non-convex closed pieces 2.5 long together, in cells of about `cell`: one
// 0.2 thick (4.8 voxels of the 64^3 grid), one 0.025 thick (0.6 voxel of the 64^3 grid, 2.4 of the
// 256^3 one); `first_thin` receives the first face of the thin one.
Mesh thick_and_thin_brackets(double cell, std::size_t& first_thin)
{
  Mesh m = test_shapes::make_l_bracket(1., 1., 0.2, 0.5, cell);
  Mesh thin = test_shapes::make_l_bracket(1., 1., 0.025, 0.5, cell);
  for(auto v : vertices(thin)) thin.point(v) = thin.point(v) + test_shapes::Vector(1.5, 0., 0.);
  first_thin = test_shapes::append(m, thin);
  return m;
}

} // namespace

TEST_CASE("a closed piece thinner than a voxel does not bound a volume of the distance field", "[decompose][pieces]")
{
  // The probes one voxel off the faces find the outside on both sides of the thin bracket at 64
  // (though its leaves are at 128), the inside at 256.
  std::size_t first_thin = 0;
  Mesh m = thick_and_thin_brackets(0.05, first_thin);
  const PD::Piece_segmentation segmented = PD::segment_pieces(m);
  REQUIRE(segmented.number_of_pieces == 2);
  CHECK(PD::splittable_pieces(m, segmented) == std::vector<std::uint8_t>{1, 1});
  const std::size_t thick_piece = segmented.piece[0], thin_piece = segmented.piece[first_thin];
  PD::Piece_segmentation pieces = segmented;
  const std::vector<std::uint8_t> at_64 = PD::volumetric_pieces(m, pieces, PD::compute_tsdf(m));
  CHECK(at_64[thick_piece] == 1);
  CHECK(at_64[thin_piece] == 0);
  pieces = segmented;
  const auto fine = PDP::combine(PDP::voxel_resolutions(std::vector<int>{64, 128, 256}), PDP::grid_resolution(256));
  const std::vector<std::uint8_t> at_256 = PD::volumetric_pieces(m, pieces, PD::compute_tsdf(m, fine), fine);
  CHECK(at_256[thick_piece] == 1);
  CHECK(at_256[thin_piece] == 1);
}

TEST_CASE("on faces much smaller than a voxel the bounding probes run once per superface", "[decompose][pieces]")
{
  // The two L-brackets of the test above in cells of 0.01, about a quarter of a voxel of the 64^3
  // grid: one probe per superface of half a voxel tells the same pieces as one per face.
  std::size_t first_thin = 0;
  Mesh m = thick_and_thin_brackets(0.01, first_thin);
  const PD::Piece_segmentation segmented = PD::segment_pieces(m);
  REQUIRE(segmented.number_of_pieces == 2);
  const std::size_t thick_piece = segmented.piece[0], thin_piece = segmented.piece[first_thin];
  const PD::Truncated_signed_distance_field tsdf = PD::compute_tsdf(m);
  PD::Piece_segmentation pieces = segmented;
  const std::vector<std::uint8_t> volumetric = PD::volumetric_pieces(m, pieces, tsdf);
  CHECK(volumetric[thick_piece] == 1);
  CHECK(volumetric[thin_piece] == 0);
  // the superfaces were used, and their fractions are those of the faces within 5% (the thin
  // bracket's few bounding faces lie along its edges, where a superface's mean normal turns most)
  const auto fim = get(CGAL::face_index, m);
  const PD::internal::Face_adjacency adj =
    PD::internal::face_adjacency_of<CGAL::Sequential_tag>(m, fim, CGAL::parameters::default_values());
  const PD::internal::Face_corners corners(m, fim, get(CGAL::vertex_point, m));
  const double cell = PD::internal::superface_cell(tsdf.voxel_size, tsdf.normalization.scale());
  const PD::internal::Superfaces sf = PD::internal::make_superfaces<CGAL::Sequential_tag>(adj, cell);
  REQUIRE(PD::internal::superfaces_pay(sf, num_faces(m)));
  const auto triangle = [&](std::size_t i) {
    PD::internal::Triangle_points t;
    for(int c = 0; c < 3; ++c)
      t[std::size_t(c)] = tsdf.normalization.to_unit(corners(i, c).x(), corners(i, c).y(), corners(i, c).z());
    return t;
  };
  const double depth = PD::internal::bounding_probe_depth * tsdf.voxel_size;
  const PD::internal::Bounding_fractions by_superface = PD::internal::piece_bounding_fractions<CGAL::Sequential_tag>(
    sf, num_faces(m), triangle, segmented, tsdf.grid, tsdf.values, depth);
  const PD::internal::Bounding_fractions by_face = PD::internal::piece_bounding_fractions<CGAL::Sequential_tag>(
    PD::internal::make_superfaces<CGAL::Sequential_tag>(adj, 1e-9), num_faces(m), triangle, segmented, tsdf.grid,
    tsdf.values, depth);
  for(std::size_t q : {thick_piece, thin_piece})
  {
    CHECK(std::abs(by_superface.bounding[q] - by_face.bounding[q]) < 0.05);
    CHECK(std::abs(by_superface.outward[q] - by_face.outward[q]) < 0.05);
  }
  CHECK(by_face.bounding[thick_piece] > 0.9);
  CHECK(by_face.bounding[thin_piece] < 0.1);
}

TEST_CASE("an assembly of sheets glued along a junction needs no distance field", "[decompose][pieces]")
{
  // The corrugated sheet alone is not convex: it may need the volumetric stages. A fin glued along
  // its line x = 0 (where z = 0), three faces at each edge, makes it an assembly of sheets whose
  // parts are its regions: no piece is splittable, and decompose() computes no distance field.
  Mesh m = test_shapes::make_wavy_sheet(24, 0.15);
  CHECK(PD::splittable_pieces(m, PD::segment_pieces(m)) == std::vector<std::uint8_t>{1});
  test_shapes::Soup fin;
  for(int j = 0; j < 24; ++j)
    for(int k = 0; k < 4; ++k)
    {
      const auto P = [](int jj, int kk) { return Point(0., -1. + 2. * jj / 24., 0.125 * kk); };
      fin.triangle(P(j, k), P(j + 1, k), P(j + 1, k + 1));
      fin.triangle(P(j, k), P(j + 1, k + 1), P(j, k + 1));
    }
  const std::size_t first_fin_face = test_shapes::append(m, fin.mesh());
  const PD::Piece_segmentation pieces = PD::segment_pieces(m);
  REQUIRE(pieces.number_of_pieces == 1);
  CHECK(PD::splittable_pieces(m, pieces) == std::vector<std::uint8_t>{0});

  std::vector<std::size_t> part(num_faces(m));
  PD::Stage_timings timings;
  PD::decompose(m, CGAL::make_property_map(part), PD::parameters::stage_timings(&timings));
  CHECK(timings.tsdf == 0.);
  CHECK(timings.fitting == 0.);
  // the fin is a part of its own
  const std::set<std::size_t> fin_parts(part.begin() + std::ptrdiff_t(first_fin_face), part.end());
  REQUIRE(fin_parts.size() == 1);
  CHECK(std::count(part.begin(), part.end(), *fin_parts.begin()) == std::ptrdiff_t(num_faces(m) - first_fin_face));
}
TEST_CASE("a closed shape with scattered non-manifold edges is a volume, not an assembly of sheets",
          "[decompose][pieces]")
{
  // A scan's defects: 40 small flaps, each glued along one edge of a face of the dumbbell (three
  // faces at that edge). Their junctions make up more than 0.1% of the edge length, as the walls
  // glued along lines of an assembly do, but each is one edge long, not a chain across the piece.
  Mesh m;
  std::vector<std::size_t> truth = test_shapes::read_shipped_shape("dumbbell", m);
  const std::size_t n = num_faces(m);
  test_shapes::Soup flaps;
  std::vector<std::size_t> flap_truth;
  double flap_edges = 0., all_edges = 0.;
  for(auto e : edges(m)) all_edges += 2. * std::sqrt(CGAL::squared_distance(m.point(source(halfedge(e, m), m)),
                                                                           m.point(target(halfedge(e, m), m))));
  std::size_t i = 0;
  for(auto f : faces(m))
  {
    if(i++ % (n / 40) != 0 || flap_truth.size() == 40) continue;
    const auto h = halfedge(f, m);
    const Point a = m.point(source(h, m)), b = m.point(target(h, m)), c = m.point(target(next(h, m), m));
    const K::Vector_3 normal = CGAL::unit_normal(a, b, c);
    const double l = std::sqrt(CGAL::squared_distance(a, b));
    flaps.triangle(b, a, CGAL::midpoint(a, b) + 0.5 * l * normal);
    flap_truth.push_back(truth[std::size_t(f)]);
    flap_edges += 3. * l;
  }
  REQUIRE(flap_truth.size() == 40);
  CHECK(flap_edges / all_edges > 0.001);
  test_shapes::append(m, flaps.mesh());
  truth.insert(truth.end(), flap_truth.begin(), flap_truth.end());
  const PD::Piece_segmentation pieces = PD::segment_pieces(m);
  REQUIRE(pieces.number_of_pieces == 1);
  CHECK(PD::splittable_pieces(m, pieces) == std::vector<std::uint8_t>{1});

  std::vector<std::size_t> part(num_faces(m));
  PD::Stage_timings timings;
  PD::decompose(m, CGAL::make_property_map(part), PD::parameters::stage_timings(&timings));
  CHECK(timings.fitting > 0.);
  const PD::Segmentation_scores s =
    PD::evaluate_segmentation(m, CGAL::make_property_map(truth), CGAL::make_property_map(part));
  INFO("mIoU " << s.mean_iou);
  CHECK(s.mean_iou >= 0.9);
}

namespace {

// An L of two plates, a horizontal one and a lower vertical one standing on its edge, and a tall
// pin standing on the horizontal plate, all closed boxes that touch. One box explains the L better
// than the plate and its pin, but the pin is small: attached to its plate, it joins it first.
// Returns the box of each face (0: horizontal plate, 1: vertical plate, 2: pin).
Mesh make_pinned_plates(std::vector<std::size_t>& box)
{
  Mesh m;
  const std::pair<Point, Point> boxes[3] = {{Point(0, 0, 0), Point(2, 2, 0.1)},
                                            {Point(0, 0, 0.1), Point(2, 0.1, 1)},
                                            {Point(0.9, 0.9, 0.1), Point(1.1, 1.1, 1.9)}};
  for(std::size_t b = 0; b < 3; ++b)
  {
    test_shapes::append(m, test_shapes::make_box(boxes[b].first, boxes[b].second, int(b) + 2));
    box.resize(num_faces(m), b);
  }
  return m;
}

} // namespace

TEST_CASE("above the default parts a small attached part joins its neighbour before large parts merge", "[hierarchy]")
{
  std::vector<std::size_t> box;
  const Mesh m = make_pinned_plates(box);
  // no merge is cheap: the default parts are the three boxes
  std::vector<std::size_t> part(num_faces(m));
  CHECK(PD::decompose(m, CGAL::make_property_map(part)) == 3);
  // two parts: the pin with its plate, not the two plates (whose box is the cheaper merge)
  CHECK(PD::decompose(m, CGAL::make_property_map(part), PDP::number_of_parts(2)) == 2);
  for(std::size_t i = 0; i < part.size(); ++i)
    for(std::size_t j = 0; j < part.size(); ++j)
      if((part[i] == part[j]) != ((box[i] == 1) == (box[j] == 1))) FAIL("faces " << i << " and " << j);
  const PD::Part_hierarchy<K> h = PD::build_part_hierarchy(m, CGAL::make_property_map(box));
  REQUIRE(h.nodes.size() == 5);
  const std::array<std::size_t, 2> first = h.nodes[3].children;
  CHECK(std::set<std::size_t>(first.begin(), first.end()) == std::set<std::size_t>{0, 2});
}

TEST_CASE("above the default parts the size of the smaller part counts in every merge, cheap or not", "[hierarchy]")
{
  // An L bracket (one piece, plates A and B, whose merge is costly: the default parts end there),
  // and apart from it two coplanar plates C and D side by side, almost touching, with a pin E
  // standing on C. C and D make one box (their merge is cheap), but they are large: E joins C first.
  std::vector<int> plate;
  Mesh m = test_shapes::make_l_bracket(1., 1., 0.1, 1., 0.25, &plate);
  std::vector<std::size_t> part(plate.begin(), plate.end());
  // dyadic corners: the sides of each box share their vertices exactly (one piece per box)
  const std::pair<Point, Point> boxes[3] = {{Point(3, 0, 0), Point(5, 2, 0.125)},
                                            {Point(5.03125, 0, 0), Point(7, 2, 0.125)},
                                            {Point(3.875, 0.875, 0.125), Point(4.125, 1.125, 1.)}};
  for(std::size_t b = 0; b < 3; ++b)
  {
    test_shapes::append(m, test_shapes::make_box(boxes[b].first, boxes[b].second, 2));
    part.resize(num_faces(m), b + 2);
  }
  const PD::Part_hierarchy<K> h = PD::build_part_hierarchy(m, CGAL::make_property_map(part));
  REQUIRE(h.number_of_leaves() == 5);
  CHECK(h.level_below_cost(5, PD::defaults::maximum_merge_cost) == 5);
  // the merges: A with B (same piece first), then E with C, then (C, E) with D
  REQUIRE(h.nodes.size() == 9);
  auto children = [&](std::size_t n) { return std::set<std::size_t>(h.nodes[n].children.begin(), h.nodes[n].children.end()); };
  CHECK(children(5) == std::set<std::size_t>{0, 1});
  CHECK(children(6) == std::set<std::size_t>{2, 4});
  CHECK(children(7) == std::set<std::size_t>{3, 6});
  // above the default parts, every merge costs at least their maximum
  for(std::size_t n = 5; n < h.nodes.size(); ++n) CHECK(h.nodes[n].merge_cost >= PD::defaults::maximum_merge_cost);
}

TEST_CASE("above the default parts two large parts of one piece wait with the contacts", "[hierarchy]")
{
  // An L bracket (one piece: plates A and B, half of the surface each) and a pin standing on A, a
  // piece of its own. Merges within a piece come first, but not that of two large halves: the pin
  // joins A before A and B merge.
  std::vector<int> plate;
  Mesh m = test_shapes::make_l_bracket(1., 1., 0.125, 1., 0.25, &plate);
  std::vector<std::size_t> part(plate.begin(), plate.end());
  test_shapes::append(m, test_shapes::make_box(Point(0.5, -0.25, 0.375), Point(0.625, 0., 0.625), 2));
  part.resize(num_faces(m), 2);
  const PD::Part_hierarchy<K> h = PD::build_part_hierarchy(m, CGAL::make_property_map(part));
  REQUIRE(h.number_of_leaves() == 3);
  CHECK(h.level_below_cost(3, PD::defaults::maximum_merge_cost) == 3);
  REQUIRE(h.nodes.size() == 5);
  auto children = [&](std::size_t n) { return std::set<std::size_t>(h.nodes[n].children.begin(), h.nodes[n].children.end()); };
  CHECK(children(3) == std::set<std::size_t>{0, 2}); // the pin with plate A
  CHECK(children(4) == std::set<std::size_t>{1, 3});
  // the superquadrics of a level come in the order of its labels: each centred in its part's box
  const std::vector<std::size_t> labels = h.labels(2);
  const std::vector<PD::Superquadric<K> > primitives = h.primitives(2);
  REQUIRE(primitives.size() == 2);
  for(std::size_t p = 0; p < 2; ++p)
  {
    CGAL::Bbox_3 box;
    for(Mesh::Face_index f : faces(m))
      if(labels[std::size_t(f)] == p)
        for(Mesh::Vertex_index v : vertices_around_face(m.halfedge(f), m)) box += m.point(v).bbox();
    const Point c = primitives[p].center();
    CHECK((c.x() > box.xmin() && c.x() < box.xmax() && c.y() > box.ymin() && c.y() < box.ymax()));
  }
}

namespace {

// Appends the box [a, b] to `m` and gives its faces `value` in `label`.
void append_labelled_box(Mesh& m, std::vector<std::size_t>& label, const Point& a, const Point& b, int subdivisions,
                         std::size_t value)
{
  test_shapes::append(m, test_shapes::make_box(a, b, subdivisions));
  label.resize(num_faces(m), value);
}

std::size_t number_of_attached_merges(const PD::Part_hierarchy<K>& h)
{
  return std::size_t(std::count_if(h.nodes.begin(), h.nodes.end(), [](const PD::Part_hierarchy_node<K>& n) {
    return n.kind == PD::Merge_kind::ATTACHED;
  }));
}

// A keyboard: a base plate, a lid standing on its back edge, `keys` small congruent boxes on the
// plate in rows of 8 (the last one wider) and a crumb on the lid. Returns per face its
// box: 0 plate, 1 lid, 2 keys, 3 crumb.
Mesh make_keyboard(std::size_t keys, std::vector<std::size_t>& box)
{
  Mesh m;
  auto add = [&](const Point& a, const Point& b, int subdivisions, std::size_t kind) {
    append_labelled_box(m, box, a, b, subdivisions, kind);
  };
  add(Point(0, 0, 0), Point(4, 2, 0.1), 4, 0);
  add(Point(0, 2, 0), Point(4, 2.1, 2), 4, 1);
  for(std::size_t k = 0; k < keys; ++k)
  {
    const double x = 0.25 + 0.45 * double(k % 8), y = 0.25 + 0.45 * double(k / 8);
    add(Point(x, y, 0.1), Point(x + (k + 1 == keys ? 0.3 : 0.2), y + 0.2, 0.15), 1, 2);
  }
  add(Point(2, 2.1, 1), Point(2.02, 2.12, 1.02), 1, 3);
  return m;
}

// Racks beside a large plate: per rack a rod and `fins` congruent fins standing on it, each fin
// about a fifth of the rod's area. Returns per face its piece: 0 the plate, then per rack its rod
// and its fins.
Mesh make_racks(std::size_t fins, std::vector<std::size_t>& piece)
{
  Mesh m;
  auto add = [&](const Point& a, const Point& b, int subdivisions) {
    append_labelled_box(m, piece, a, b, subdivisions, piece.empty() ? 0 : piece.back() + 1);
  };
  add(Point(0, 0, 0), Point(6, 6, 0.1), 2);
  for(double y : {1., 4.})
  {
    add(Point(8, y, 0), Point(12, y + 0.1, 0.1), 2);
    for(std::size_t k = 0; k < fins; ++k)
    {
      const double x = 8.1 + 0.33 * double(k);
      add(Point(x, y, 0.1), Point(x + 0.1, y + 0.05, 1.1), 1);
    }
  }
  return m;
}

} // namespace

TEST_CASE("keys laid out on a plate and a crumb join the piece they sit on; the hierarchy keeps them apart",
          "[hierarchy][pieces][decompose]")
{
  std::vector<std::size_t> box;
  const Mesh m = make_keyboard(25, box);
  std::vector<std::size_t> part(num_faces(m));
  PD::Part_hierarchy<K> h;
  CHECK(PD::decompose(m, CGAL::make_property_map(part), PDP::part_hierarchy(&h)) == 2);
  // the plate with its keys, the lid with its crumb
  for(std::size_t i = 0; i < part.size(); ++i)
    if((part[i] == part[0]) != (box[i] == 0 || box[i] == 2)) FAIL("face " << i << " of box kind " << box[i]);
  // every key and the crumb are leaves of their own, joined to their group by attached merges
  CHECK(h.number_of_leaves() >= 28);
  CHECK(number_of_attached_merges(h) == 26);
  // a level of the hierarchy reaches the keys: each key a part of its own
  const std::vector<std::size_t> fine = h.labels(h.default_number_of_parts + 26);
  std::set<std::size_t> key_parts;
  for(std::size_t i = 0; i < fine.size(); ++i)
    if(box[i] == 2) key_parts.insert(fine[i]);
  CHECK(key_parts.size() == 25);
}

TEST_CASE("a few congruent pieces on a plate are not a pattern: they stay parts", "[hierarchy][pieces][decompose]")
{
  std::vector<std::size_t> box;
  const Mesh m = make_keyboard(4, box);
  std::vector<std::size_t> part(num_faces(m));
  // plate, lid with its crumb, and the four keys
  CHECK(PD::decompose(m, CGAL::make_property_map(part)) == 6);
  std::set<std::size_t> key_parts;
  for(std::size_t i = 0; i < part.size(); ++i)
    if(box[i] == 2) key_parts.insert(part[i]);
  CHECK(key_parts.size() == 4);
}

TEST_CASE("congruent fins on several small rods are one pattern: each rack is one default part",
          "[hierarchy][pieces]")
{
  // 24 fins, 12 per rod: a pattern although no rod holds 20 fins or is 10 times a fin's area
  std::vector<std::size_t> piece;
  const Mesh m = make_racks(12, piece);
  const PD::Part_hierarchy<K> h = PD::build_part_hierarchy(m, CGAL::make_property_map(piece));
  REQUIRE(h.number_of_leaves() == 27);
  REQUIRE(h.level_below_cost(27, PD::defaults::maximum_merge_cost) == 3);
  const std::vector<std::size_t> labels = h.labels(3);
  const std::size_t second_rack = 1 + 13; // the piece of the second rod
  std::map<std::size_t, std::set<std::size_t> > parts_of_rack;
  for(std::size_t i = 0; i < labels.size(); ++i)
    parts_of_rack[piece[i] == 0 ? 0 : piece[i] < second_rack ? 1 : 2].insert(labels[i]);
  for(std::size_t r = 0; r < 3; ++r) CHECK(parts_of_rack[r].size() == 1);
  CHECK(parts_of_rack[1] != parts_of_rack[2]);
  CHECK(number_of_attached_merges(h) == 24);
  // 18 fins are too few for a pattern: none is attached
  std::vector<std::size_t> few_piece;
  const Mesh few = make_racks(9, few_piece);
  CHECK(number_of_attached_merges(PD::build_part_hierarchy(few, CGAL::make_property_map(few_piece))) == 0);
}

TEST_CASE("flat pieces side by side that tile one plate are one default part; staggered, they stay apart",
          "[hierarchy][pieces]")
{
  for(double stagger : {0., 0.3})
  {
    // an L-bracket, one piece in two parts that do not merge by default, and 5 rows of keys
    std::vector<int> plate;
    Mesh m = test_shapes::make_l_bracket(12., 12., 0.5, 12., 2., &plate);
    std::vector<std::size_t> part(plate.begin(), plate.end());
    for(std::size_t r = 0; r < 5; ++r)
    {
      const double y = 0.52 * double(r), z = r % 2 ? stagger : 0.;
      append_labelled_box(m, part, Point(14, y, z), Point(18, y + 0.5, z + 0.05), 1, 2 + r);
    }
    const PD::Part_hierarchy<K> h = PD::build_part_hierarchy(m, CGAL::make_property_map(part));
    REQUIRE(h.number_of_leaves() == 7);
    const std::size_t parts = h.level_below_cost(7, PD::defaults::maximum_merge_cost);
    CAPTURE(stagger);
    CHECK(parts == (stagger == 0. ? 3 : 7));
    CHECK(number_of_attached_merges(h) == (stagger == 0. ? 4 : 0));
  }
}

namespace {

// A one-sided figure cut out of a sheet, as an OBJ file: a round body of radius 1 and three limbs
// 0.5 wide reaching radius 2.6, at 90, 210 and 330 degrees, on a grid of step 0.1 (two triangles
// per cell whose centre is in the figure). `bend` lifts the sheet by bend (x^2 + y^2): a relief.
std::string cut_out_figure_obj(double bend)
{
  const double pi = 3.14159265358979323846, step = 0.1;
  const int n = 60; // cells per side over [-3, 3]
  auto inside = [&](double x, double y) {
    if(x * x + y * y <= 1.) return true;
    for(double degrees : {90., 210., 330.})
    {
      const double c = std::cos(degrees * pi / 180.), s = std::sin(degrees * pi / 180.);
      const double along = c * x + s * y, across = -s * x + c * y;
      if(along >= 0. && along <= 2.6 && std::abs(across) <= 0.25) return true;
    }
    return false;
  };
  std::ostringstream obj;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i)
    {
      const double x = -3. + step * i, y = -3. + step * j;
      obj << "v " << x << ' ' << y << ' ' << bend * (x * x + y * y) << '\n';
    }
  auto id = [&](int i, int j) { return j * (n + 1) + i + 1; };
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
      if(inside(-3. + step * (i + 0.5), -3. + step * (j + 0.5)))
        obj << "f " << id(i, j) << ' ' << id(i + 1, j) << ' ' << id(i + 1, j + 1) << '\n'
            << "f " << id(i, j) << ' ' << id(i + 1, j + 1) << ' ' << id(i, j + 1) << '\n';
  return obj.str();
}

} // namespace

TEST_CASE("a one-sided cut-out figure or relief is decomposed as its inflated solid: its limbs are parts",
          "[decompose][pieces][open]")
{
  for(double bend : {0., 0.1})
  {
    INFO("bend " << bend);
    const std::string path = "pd_test_cut_out_figure.obj";
    {
      std::ofstream out(path);
      out << cut_out_figure_obj(bend);
    }
    Mesh m;
    PD::IO::read_triangle_mesh(path, m);
    std::remove(path.c_str());
    std::vector<std::size_t> part(num_faces(m));
    const std::size_t K = PD::decompose(m, CGAL::make_property_map(part));
    CHECK(K >= 4);
    // the part of the face nearest to a point of the figure's plane
    auto part_at = [&](double x, double y) {
      std::size_t best = 0;
      double best_d = std::numeric_limits<double>::infinity();
      for(auto f : faces(m))
      {
        const Point c = CGAL::centroid(m.point(source(halfedge(f, m), m)), m.point(target(halfedge(f, m), m)),
                                       m.point(target(next(halfedge(f, m), m), m)));
        const double d = CGAL::square(c.x() - x) + CGAL::square(c.y() - y);
        if(d < best_d) { best_d = d; best = std::size_t(f); }
      }
      return part[best];
    };
    const std::size_t body = part_at(0., 0.), a = part_at(0., 2.4), b = part_at(-2.08, -1.2), c = part_at(2.08, -1.2);
    CHECK(std::set<std::size_t>{body, a, b, c}.size() == 4);
  }
}

namespace {

// A closed cup of radius 1 and height 2 whose wall and bottom are `thickness` thick: the profile
// (outer bottom, outer wall, rim, inner wall, inner bottom) revolved in `n` steps. Per face, 1 if
// it lies on the wall (outer or inner) between heights 0.2 and 1.8.
Mesh make_thin_cup(double thickness, int n, std::vector<std::uint8_t>& wall)
{
  const double pi = 3.14159265358979323846;
  const std::vector<std::array<double, 2> > corners = {
    {{0., 0.}}, {{1., 0.}}, {{1., 2.}}, {{1. - thickness, 2.}}, {{1. - thickness, thickness}}, {{0., thickness}}};
  std::vector<std::array<double, 2> > profile;
  for(std::size_t c = 0; c + 1 < corners.size(); ++c)
  {
    const double length = std::hypot(corners[c + 1][0] - corners[c][0], corners[c + 1][1] - corners[c][1]);
    const int steps = (std::max)(1, int(length / 0.1));
    for(int s = 0; s < steps; ++s)
      profile.push_back({{corners[c][0] + (corners[c + 1][0] - corners[c][0]) * s / steps,
                          corners[c][1] + (corners[c + 1][1] - corners[c][1]) * s / steps}});
  }
  profile.push_back(corners.back());
  Mesh m;
  std::vector<std::vector<Mesh::Vertex_index> > ring(profile.size());
  for(std::size_t r = 0; r < profile.size(); ++r)
    for(int k = 0; k < (profile[r][0] == 0. ? 1 : n); ++k)
    {
      const double a = 2. * pi * k / n;
      ring[r].push_back(m.add_vertex(Point(profile[r][0] * std::cos(a), profile[r][0] * std::sin(a), profile[r][1])));
    }
  for(std::size_t r = 0; r + 1 < profile.size(); ++r)
    for(int k = 0; k < n; ++k)
    {
      auto at = [&](std::size_t q, int j) { return ring[q].size() == 1 ? ring[q][0] : ring[q][std::size_t(j % n)]; };
      const bool on_wall = std::abs(profile[r][0] - profile[r + 1][0]) < 1e-12 && profile[r][1] > 0.2 &&
                           profile[r][1] < 1.8 && profile[r + 1][1] > 0.2 && profile[r + 1][1] < 1.8;
      // outward: the profile runs counterclockwise around the solid seen from +y
      if(ring[r].size() > 1) { m.add_face(at(r, k), at(r, k + 1), at(r + 1, k + 1)); wall.push_back(on_wall); }
      if(ring[r + 1].size() > 1) { m.add_face(at(r, k), at(r + 1, k + 1), at(r + 1, k)); wall.push_back(on_wall); }
    }
  return m;
}

} // namespace

TEST_CASE("a cup whose wall is thinner than a voxel has its wall in one part", "[decompose][sheet_merge]")
{
  for(double thickness : {0.01, 0.03})
  {
    INFO("thickness " << thickness);
    std::vector<std::uint8_t> wall;
    const Mesh m = make_thin_cup(thickness, 64, wall);
    REQUIRE(CGAL::is_closed(m));
    std::vector<std::size_t> part(num_faces(m));
    const std::size_t K = PD::decompose(m, CGAL::make_property_map(part));
    CHECK(K <= 3);
    std::set<std::size_t> wall_parts;
    for(std::size_t i = 0; i < part.size(); ++i)
      if(wall[i]) wall_parts.insert(part[i]);
    CHECK(wall_parts.size() == 1);
  }
}
