// Fits superquadrics to a mesh (paper Alg. A.2) and writes them as one triangle mesh.
//
// Usage: superquadric_example [mesh.off|obj|ply|stl]
// Without argument, the shipped table (or, if it is missing, a generated shape) is used.
// The primitives are written in the input coordinates to <input>_primitives.off, next to the
// input (in the current directory for the default mesh), and their parameters are printed with
// the leaves of the adaptive grid each claimed and their volume.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Part_decomposition/IO/read_mesh.h>
#include <CGAL/Part_decomposition/Superquadric.h>
#include <CGAL/Part_decomposition/flow_freeze_prior.h>
#include <CGAL/Part_decomposition/superquadric_fitting.h>
#include <CGAL/Part_decomposition/tsdf.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
namespace PD = CGAL::Part_decomposition;
typedef CGAL::Parallel_if_available_tag Concurrency;

int main(int argc, char** argv)
{
  std::string input = argc > 1 ? argv[1] : std::string(PD_EXAMPLE_DATA_DIR) + "/table.off";
  std::string output;
  Mesh mesh;
  if(argc > 1 || std::ifstream(input).good())
  {
    try
    {
      PD::IO::read_triangle_mesh(input, mesh);
    }
    catch(const PD::Invalid_input& e)
    {
      std::cerr << "Cannot read " << input << ": " << e.what() << std::endl;
      return EXIT_FAILURE;
    }
    const std::string stem = input.substr(0, input.find_last_of('.'));
    output = (argc > 1 ? stem : stem.substr(stem.find_last_of('/') + 1)) + "_primitives.off";
  }
  else
  {
    // a generated shape: a box-like body with a round knob, overlapping
    const PD::Superquadric<K>::Rotation I = {{1, 0, 0, 0, 1, 0, 0, 0, 1}};
    PD::Superquadric<K>({{0.5, 0.3, 0.2}}, 0.2, 0.2, I, Point(0, 0, 0)).to_triangle_mesh(mesh, 40);
    PD::Superquadric<K>({{0.18, 0.18, 0.18}}, 1., 1., I, Point(0.6, 0, 0)).to_triangle_mesh(mesh, 40);
    output = "generated_primitives.off";
  }
  std::cout << input << ": " << num_faces(mesh) << " faces" << std::endl;

  const PD::Hierarchical_prior prior = PD::compute_flow_freeze_prior<Concurrency>(mesh);
  // the distance field on the grid the prior asks for, as decompose() computes it
  const PD::Truncated_signed_distance_field tsdf = PD::compute_tsdf<Concurrency>(mesh, prior);
  const PD::Superquadric_fitting_result<K> fit = PD::fit_superquadrics<Concurrency, K>(prior, tsdf);

  std::cout << fit.primitives.size() << " superquadrics (" << fit.number_of_seeds << " seeds, "
            << fit.number_of_solves << " solves, " << fit.seconds << " s) on " << tsdf.grid.number_of_leaves()
            << " leaves; in input coordinates:" << std::endl;
  const double scale = tsdf.normalization.scale(); // input lengths to normalized ones
  Mesh out;
  for(std::size_t k = 0; k < fit.input_primitives.size(); ++k)
  {
    const PD::Superquadric<K>& sq = fit.input_primitives[k];
    const auto a = sq.scales();
    // the leaves differ in size: the claimed volume is the sum of theirs
    double volume = 0.;
    for(std::size_t l : fit.claimed_leaves[k]) volume += tsdf.grid.volume(l);
    std::cout << "  " << k << ": stage " << fit.stage_resolution[k] << (fit.body_seeded[k] ? " body" : " surface")
              << ", centre (" << sq.center() << "), semi-axes (" << a[0] << ", " << a[1] << ", " << a[2]
              << "), eps (" << sq.epsilon1() << ", " << sq.epsilon2() << "), axis x (" << sq.axis(0) << "), "
              << "claimed " << fit.claimed_leaves[k].size() << " leaves of volume " << volume / (scale * scale * scale)
              << " (its own " << sq.volume() << ")" << std::endl;
    sq.to_triangle_mesh(out, 24);
  }
  if(!CGAL::IO::write_polygon_mesh(output, out, CGAL::parameters::stream_precision(17)))
  {
    std::cerr << "Cannot write " << output << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "wrote " << output << std::endl;
  return EXIT_SUCCESS;
}
