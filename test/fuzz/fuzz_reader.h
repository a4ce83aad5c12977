// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// What every reader promises (IO/read_*.h), checked on arbitrary bytes: it never throws; it
// either fills a consistent domain (segments between two distinct points, one marker per
// segment or none, labels likewise, coordinates finite and at most 1e150), which the domain
// checks (extract_loops()) then accept or reject with Meshing_error only, or it leaves the
// domain empty with one message that names the source. The point readers are checked both
// rejecting duplicate points and keeping them.

#ifndef QM2_FUZZ_READER_H
#define QM2_FUZZ_READER_H

#include "fuzz_require.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/Domain_loops_2.h>
#include <CGAL/Quad_mesher_2/IO/read_node.h>
#include <CGAL/Quad_mesher_2/Meshing_error.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

namespace qm2_fuzz {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Quad_mesher_2::Domain_2<K> Domain;

// the name the readers are given, which every message must start with
const std::string source = "fuzz-input";

inline bool is_coordinate(const K::Point_2& p)
{
  return std::isfinite(p.x()) && std::isfinite(p.y()) && std::abs(p.x()) <= 1e150 && std::abs(p.y()) <= 1e150;
}

inline void check_domain(const Domain& d)
{
  for(const K::Point_2& p : d.points)
    require(is_coordinate(p), "points are finite and at most 1e150");
  for(const K::Point_2& p : d.holes)
    require(is_coordinate(p), "hole points are finite and at most 1e150");
  for(const Domain::Segment& s : d.segments)
    require(s[0] < d.points.size() && s[1] < d.points.size() && s[0] != s[1], "segments join two points");
  require(d.segment_markers.empty() || d.segment_markers.size() == d.segments.size(), "one marker per segment");
  require(d.point_labels.empty() || d.point_labels.size() == d.points.size(), "one label per point");
  require(d.segment_labels.empty() || d.segment_labels.size() == d.segments.size(), "one label per segment");
  require(d.hole_labels.empty() || d.hole_labels.size() == d.holes.size(), "one label per hole");
  if(d.is_point_cloud())
    return;
  try {
    CGAL::Quad_mesher_2::extract_loops(d);
  } catch(const CGAL::Quad_mesher_2::Meshing_error&) {
  }
}

// `read(in, domain, error)` on the bytes
template <class Read>
void check_read(const std::uint8_t* data, std::size_t size, Read read)
{
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  Domain domain;
  domain.points.emplace_back(1, 2); // a reader starts from an empty domain, whatever it is given
  std::string error;
  if(read(in, domain, &error)) {
    require(!domain.points.empty(), "a domain read has points");
    check_domain(domain);
    return;
  }
  require(domain.points.empty() && domain.segments.empty() && domain.holes.empty()
            && domain.segment_markers.empty() && domain.point_labels.empty(),
          "a failed read leaves the domain empty");
  require(error.compare(0, source.size(), source) == 0, "the message names the source: " + error);
}

// a reader's stream overload, and a point reader's, which also says what to do with duplicates
typedef bool (*Reader)(std::istream&, Domain&, std::string*, const std::string&);
typedef bool (*Point_reader)(std::istream&, Domain&, std::string*, const std::string&,
                             CGAL::Quad_mesher_2::IO::Duplicate_points);

inline void check_reader(const std::uint8_t* data, std::size_t size, Reader reader)
{
  check_read(data, size, [&](std::istream& in, Domain& d, std::string* error) { return reader(in, d, error, source); });
}

// both rejecting duplicate points and keeping them
inline void check_reader(const std::uint8_t* data, std::size_t size, Point_reader reader)
{
  using CGAL::Quad_mesher_2::IO::Duplicate_points;
  for(Duplicate_points duplicates : { Duplicate_points::REJECT, Duplicate_points::KEEP })
    check_read(data, size,
               [&](std::istream& in, Domain& d, std::string* error) { return reader(in, d, error, source, duplicates); });
}

} // namespace qm2_fuzz

#endif // QM2_FUZZ_READER_H
