// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_IO_READ_DOMAIN_H
#define CGAL_QUAD_MESHER_2_IO_READ_DOMAIN_H

#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/IO/file_extension.h>
#include <CGAL/Quad_mesher_2/IO/read_WKT.h>
#include <CGAL/Quad_mesher_2/IO/read_node.h>
#include <CGAL/Quad_mesher_2/IO/read_poly.h>
#include <CGAL/Quad_mesher_2/IO/read_xy.h>

#include <cctype>
#include <string>

namespace CGAL {
namespace Quad_mesher_2 {
namespace IO {

/// \ingroup PkgQuadMesher2IO
/// Reads the domain in `filename` into `out`, choosing the reader by the extension
/// (case-insensitive): `.poly` (`read_poly()`), `.node` (`read_node()`), `.xy`, `.txt`,
/// `.pts`, `.dat` (`read_xy()`), `.wkt` (`read_WKT()`). Any other extension is an error
/// (`FILE: unknown file extension ...`), and so is a file that is not a regular file (a
/// directory, a FIFO, a device; a symbolic link counts as the file it names). Returns `false` on failure, with `out` empty and one
/// message in `*error`. Never throws. `duplicates` applies to the point files (`.node`, `x y`);
/// a `.poly` or WKT input always rejects duplicate points.
template <class K>
bool read_domain(const std::string& filename, Domain_2<K>& out, std::string* error = nullptr,
                 Duplicate_points duplicates = Duplicate_points::REJECT)
{
  std::string msg;
  if(!internal::is_regular_or_missing(filename, msg)) { // before the extension: /dev/zero has none
    out = Domain_2<K>();
    internal::set_error(error, msg);
    return false;
  }
  const std::string ext = file_extension(filename);
  if(ext == ".poly") return read_poly(filename, out, error);
  if(ext == ".node") return read_node(filename, out, error, duplicates);
  if(ext == ".xy" || ext == ".txt" || ext == ".pts" || ext == ".dat") return read_xy(filename, out, error, duplicates);
  if(ext == ".wkt") return read_WKT(filename, out, error);
  out = Domain_2<K>();
  internal::set_error(error, filename + ": unknown file extension " +
                               (ext.empty() ? std::string("(none)") : "\"" + ext + "\"") +
                               " (expected .poly, .node, .xy, .txt, .pts, .dat or .wkt)");
  return false;
}

} // namespace IO
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_IO_READ_DOMAIN_H
