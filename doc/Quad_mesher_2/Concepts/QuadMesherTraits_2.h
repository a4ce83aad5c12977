/*!
\ingroup PkgQuadMesher2Concepts
\cgalConcept

The concept `QuadMesherTraits_2` describes the geometric types and function objects that
`CGAL::Quad_mesher_2::Balanced_quadtree_2`, `CGAL::Quad_mesher_2::Quadtree_mesher_2`,
`CGAL::Quad_mesher_2::Mesh_criteria_2`, `CGAL::Quad_mesher_2::Domain_2`,
`CGAL::Quad_mesher_2::extract_loops()` and `CGAL::Quad_mesher_2::domain_area()`, the curve
decomposition (`CGAL::Quad_mesher_2::decompose_closed_spline()`,
`CGAL::Quad_mesher_2::decompose_domain_curves()`), the narrow-region sizing and the
buffer-zone clearance use. The list is exactly what the package's headers call on the
traits (every `..._object()` in `include/`):
- the quadtree and the points stage: the point coordinates, the extremes of an
  iso-rectangle, `Less_x_2` and `Less_y_2` (bounding box of the input), `Less_xy_2` and
  `Equal_2` (merging duplicate points), `Construct_point_2` (lattice points, the widened
  bounding box, the moved vertices, the narrow-region samples) and
  `Construct_iso_rectangle_2` (cells);
- the boundary loops (`Domain_loops_2.h`, also run by the curve decomposition):
  `Orientation_2`, `Collinear_are_ordered_along_line_2`, `Construct_segment_2` and
  `Do_intersect_2` (crossing, touching and overlapping segments), `Compare_x_2`
  (point in loop), `Construct_bbox_2` (box filters) and `Compute_area_2` (`domain_area()`);
- the buffer-zone clearance (`internal/buffer_zone_clearance.h`): `Orientation_2`,
  `Compare_x_2`, `Construct_segment_2`, `Construct_bbox_2` and
  `Compare_squared_distance_2` (criterion 3);
- the buffer stages (`internal/buffer_zone.h` and the stage headers that work on it):
  `Construct_point_2`, `Compute_x_2` and `Compute_y_2` (points to and from the doubles the
  searches move them in, new boundary points on an input segment), `Orientation_2` (the
  exact check of every quad they make or change), and `Construct_segment_2` and
  `Compare_squared_distance_2` (whether a moved core boundary edge keeps its clearance from
  the boundary).

The searches themselves (projections onto the boundary, bisectors, the optimiser's moves and
its fold test) work on doubles through a fixed kernel, `CGAL::Epick`
(`internal/approximate_kernel.h`): its constructions round, its predicates are exact on the
doubles the moved points will have, whatever `FT` is. The narrow-region sizing
(`internal/narrow_regions.h`) measures gaps on that kernel too, and decides which corners are
convex with the traits' `Orientation_2` on the input points. A test
(`test/test_traits_and_headers.cpp`) compiles and runs the mesher through every stage with an
archetype that provides nothing else.

The number type `FT` must be constructible from `double`, comparable with `operator<`,
support `+`, `-` and `*` (the points stage moves vertices by \f$ x + f (p_x - w_x)\f$), and be
accepted by `CGAL::to_double()` and `CGAL::to_interval()` (any model of `FieldNumberType`
that is `RealEmbeddable`). The mesher decides point location with exact comparisons of `FT`
values against lattice coordinates, which are exact `double` values (see the user manual,
section "Exact arithmetic").

\cgalHasModelsBegin
\cgalHasModelsBare{Any model of the `Kernel` concept; in particular:}
\cgalHasModels{CGAL::Exact_predicates_inexact_constructions_kernel}
\cgalHasModels{CGAL::Exact_predicates_exact_constructions_kernel}
\cgalHasModelsEnd

<b>Not covered by this concept.</b> Functions that take a point type rather than a traits
class (`CGAL::Quad_mesher_2::compute_quality()`, the writers `write_MSH()`, `write_VTU()`,
`write_OFF()`, `write_SVG()`) call `p.x()` and `p.y()` on the point directly. The readers in
`CGAL::Quad_mesher_2::IO` construct points with `Construct_point_2`;
`CGAL::Quad_mesher_2::loop_polygon_2()` returns a `CGAL::Polygon_2<GeomTraits>`; `read_WKT()` also calls
`CGAL::is_simple_2()`, `CGAL::bounded_side_2()`, `CGAL::orientation_2()` with the traits (so
its kernel must be a model of `PolygonTraits_2` as well) and `Point_2::bbox()`.

\sa `CGAL::Quad_mesher_2::Quadtree_mesher_2<GeomTraits>`
\sa `CGAL::Quad_mesher_2::Balanced_quadtree_2<GeomTraits>`
*/
class QuadMesherTraits_2
{
public:

/// \name Types
/// @{

/*!
The number type of the coordinates. See the requirements above.
*/
typedef unspecified_type FT;

/*!
The point type; must be copyable and default constructible.
*/
typedef unspecified_type Point_2;

/*!
The iso-oriented rectangle type: the bounding box of the input and the geometry of a
quadtree cell.
*/
typedef unspecified_type Iso_rectangle_2;

/*!
The segment type: the boundary segments of a domain.
*/
typedef unspecified_type Segment_2;

/// @}

/// \name Function Object Types
/// @{

/*!
A function object providing `FT operator()(const Point_2& p)`, which returns the
\f$ x\f$-coordinate of `p`.
*/
typedef unspecified_type Compute_x_2;

/*!
A function object providing `FT operator()(const Point_2& p)`, which returns the
\f$ y\f$-coordinate of `p`.
*/
typedef unspecified_type Compute_y_2;

/*!
A function object providing `FT operator()(const Iso_rectangle_2& r)`, which returns the
smallest \f$ x\f$-coordinate of `r`.
*/
typedef unspecified_type Compute_xmin_2;

/*!
A function object providing `FT operator()(const Iso_rectangle_2& r)`, which returns the
smallest \f$ y\f$-coordinate of `r`.
*/
typedef unspecified_type Compute_ymin_2;

/*!
A function object providing `FT operator()(const Iso_rectangle_2& r)`, which returns the
largest \f$ x\f$-coordinate of `r`.
*/
typedef unspecified_type Compute_xmax_2;

/*!
A function object providing `FT operator()(const Iso_rectangle_2& r)`, which returns the
largest \f$ y\f$-coordinate of `r`.
*/
typedef unspecified_type Compute_ymax_2;

/*!
A predicate providing `bool operator()(const Point_2& p, const Point_2& q)`, which returns
`true` iff the \f$ x\f$-coordinate of `p` is smaller than that of `q`.
*/
typedef unspecified_type Less_x_2;

/*!
A predicate providing `bool operator()(const Point_2& p, const Point_2& q)`, which returns
`true` iff the \f$ y\f$-coordinate of `p` is smaller than that of `q`.
*/
typedef unspecified_type Less_y_2;

/*!
A predicate providing `bool operator()(const Point_2& p, const Point_2& q)`, which returns
`true` iff `p` is lexicographically smaller than `q` (by \f$ x\f$, then by \f$ y\f$).
*/
typedef unspecified_type Less_xy_2;

/*!
A predicate providing `bool operator()(const Point_2& p, const Point_2& q)`, which returns
`true` iff `p` and `q` are equal.
*/
typedef unspecified_type Equal_2;

/*!
A function object providing `Point_2 operator()(const FT& x, const FT& y)`, which
constructs the point \f$ (x, y)\f$ (lattice points, the corners of the widened bounding box,
and the moved vertices of the points stage).
*/
typedef unspecified_type Construct_point_2;

/*!
A function object providing
- `Iso_rectangle_2 operator()(const Point_2& p, const Point_2& q)`, which constructs the
  rectangle with lower-left corner `p` and upper-right corner `q` (used for cells), and
- `Iso_rectangle_2 operator()(const Point_2& left, const Point_2& right, const Point_2& bottom, const Point_2& top)`,
  which constructs the smallest rectangle whose sides pass through the four points (used for
  the bounding box of the input).
*/
typedef unspecified_type Construct_iso_rectangle_2;

/*!
A predicate providing `Comparison_result operator()(const Point_2& p, const Point_2& q)`,
which compares the \f$ x\f$-coordinates of `p` and `q`.
*/
typedef unspecified_type Compare_x_2;

/*!
A predicate providing `Orientation operator()(const Point_2& p, const Point_2& q, const Point_2& r)`,
which returns `LEFT_TURN`, `RIGHT_TURN` or `COLLINEAR`.
*/
typedef unspecified_type Orientation_2;

/*!
A predicate providing `bool operator()(const Point_2& p, const Point_2& q, const Point_2& r)`,
which, for collinear points, returns `true` iff `q` lies between `p` and `r` (or equals one
of them).
*/
typedef unspecified_type Collinear_are_ordered_along_line_2;

/*!
A function object providing `FT operator()(const Point_2& p, const Point_2& q, const Point_2& r)`,
which returns the signed area of the triangle `pqr`.
*/
typedef unspecified_type Compute_area_2;

/*!
A function object providing `CGAL::Bbox_2 operator()(const Point_2& p)`, a box of `double`
values that contains `p` (used only as a conservative filter).
*/
typedef unspecified_type Construct_bbox_2;

/*!
A function object providing `Segment_2 operator()(const Point_2& p, const Point_2& q)`.
*/
typedef unspecified_type Construct_segment_2;

/*!
A predicate providing `bool operator()(const Segment_2& s, const Segment_2& t)`, which
returns `true` iff the closed segments `s` and `t` meet.
*/
typedef unspecified_type Do_intersect_2;

/*!
A predicate providing `Comparison_result operator()(const Point_2& p, const Segment_2& s, const FT& d2)`,
which compares the squared distance from `p` to `s` with `d2`.
*/
typedef unspecified_type Compare_squared_distance_2;

/// @}

/// \name Access to Function Objects
/// @{

/*!

*/
Compute_x_2 compute_x_2_object() const;

/*!

*/
Compute_y_2 compute_y_2_object() const;

/*!

*/
Compute_xmin_2 compute_xmin_2_object() const;

/*!

*/
Compute_ymin_2 compute_ymin_2_object() const;

/*!

*/
Compute_xmax_2 compute_xmax_2_object() const;

/*!

*/
Compute_ymax_2 compute_ymax_2_object() const;

/*!

*/
Less_x_2 less_x_2_object() const;

/*!

*/
Less_y_2 less_y_2_object() const;

/*!

*/
Less_xy_2 less_xy_2_object() const;

/*!

*/
Equal_2 equal_2_object() const;

/*!

*/
Construct_point_2 construct_point_2_object() const;

/*!

*/
Construct_iso_rectangle_2 construct_iso_rectangle_2_object() const;

/*!

*/
Compare_x_2 compare_x_2_object() const;

/*!

*/
Orientation_2 orientation_2_object() const;

/*!

*/
Collinear_are_ordered_along_line_2 collinear_are_ordered_along_line_2_object() const;

/*!

*/
Compute_area_2 compute_area_2_object() const;

/*!

*/
Construct_bbox_2 construct_bbox_2_object() const;

/*!

*/
Construct_segment_2 construct_segment_2_object() const;

/*!

*/
Do_intersect_2 do_intersect_2_object() const;

/*!

*/
Compare_squared_distance_2 compare_squared_distance_2_object() const;

/// @}

}; /* end QuadMesherTraits_2 */
