/*!
\ingroup PkgPartDecompositionConcepts
\cgalConcept

The concept `PartDecompositionTraits` describes the geometric types and functors required by the
functions of this package. Every numerical stage (curvature, distance field, superquadric
fitting, voting) converts the coordinates of the points to `double` with `CGAL::to_double()` and
computes in double precision; its own search structures use a \cgal kernel on `double`
internally. The traits class gives the point type of the mesh, the types of the returned
superquadrics, and the few constructions done on the input points (face normals and areas).

\cgalHasModel All models of the <a href="https://doc.cgal.org/5.5.1/Kernel_23/classKernel.html">`Kernel`</a>
concept, among them `CGAL::Exact_predicates_inexact_constructions_kernel` (recommended) and
`CGAL::Simple_cartesian<double>`.
*/
class PartDecompositionTraits
{
public:
  /// \name Types
  /// @{

  /// a model of `FieldNumberType` convertible to `double` with `CGAL::to_double()`
  typedef unspecified_type FT;
  /// the point type, constructible from three `double`
  typedef unspecified_type Point_3;
  /// the vector type
  typedef unspecified_type Vector_3;
  /// @}

  /// \name Functors
  /// @{

  /// a function object `Vector_3 operator()(const Point_3& p, const Point_3& q)` returning `q - p`
  typedef unspecified_type Construct_vector_3;
  /// a function object `Vector_3 operator()(const Vector_3& u, const Vector_3& v)` returning the
  /// cross product of `u` and `v`
  typedef unspecified_type Construct_cross_product_vector_3;
  /// a function object `FT operator()(const Point_3& p, const Point_3& q, const Point_3& r)` returning
  /// the squared area of the triangle `pqr` (used by the area-weighted sampling of the benchmark's
  /// evaluation metrics)
  typedef unspecified_type Compute_squared_area_3;
  /// @}

  /// \name Operations
  /// @{

  /// returns the functor that constructs vectors.
  Construct_vector_3 construct_vector_3_object() const;
  /// returns the cross-product functor.
  Construct_cross_product_vector_3 construct_cross_product_vector_3_object() const;
  /// returns the squared-area functor.
  Compute_squared_area_3 compute_squared_area_3_object() const;
  /// @}
};
