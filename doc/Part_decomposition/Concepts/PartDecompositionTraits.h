/*!
\ingroup PkgPartDecompositionConcepts
\cgalConcept

The concept `PartDecompositionTraits` describes the geometric types required by the functions of
this package. The numerical stages (curvature, distance field, superquadric fitting) convert
coordinates to `double` with `CGAL::to_double()`; the kernel is only used for its point and vector
types, the AABB tree and the kd-tree.

\cgalRefines `AABBGeomTraits`, `SearchTraits`

\cgalHasModel All models of `Kernel`, among them `CGAL::Exact_predicates_inexact_constructions_kernel`
(recommended) and `CGAL::Simple_cartesian<double>`.
*/
class PartDecompositionTraits
{
public:
  /// \name Types
  /// @{

  /// a model of `FieldNumberType` convertible to `double` with `CGAL::to_double()`
  typedef unspecified_type FT;
  /// the point type
  typedef unspecified_type Point_3;
  /// the vector type
  typedef unspecified_type Vector_3;
  /// the triangle type, used by the AABB tree of the distance field
  typedef unspecified_type Triangle_3;
  /// @}
};
