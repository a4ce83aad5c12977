// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_BOX_TREE_H
#define CGAL_QUAD_MESHER_2_INTERNAL_BOX_TREE_H

#include <CGAL/Bbox_2.h>
#include <CGAL/assertions.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// A bounding-volume hierarchy over boxes (median split on the longer axis), for box-overlap
/// queries in O(log n + output) on well-spread input, whatever the clustering of the data.
class Box_tree
{
public:
  explicit Box_tree(const std::vector<Bbox_2>& boxes) : m_boxes(boxes)
  {
    m_items.resize(boxes.size());
    for(std::size_t i = 0; i < boxes.size(); ++i) m_items[i] = static_cast<std::uint32_t>(i);
    if(!boxes.empty()) {
      m_nodes.reserve(2 * (boxes.size() / leaf_size + 1));
      build(0, boxes.size());
    }
  }

  /// Calls `f(i)` for every box `i` that overlaps `q` (closed boxes).
  template <class F>
  void query(const Bbox_2& q, F&& f) const
  {
    if(m_nodes.empty()) return;
    // on the call stack, not the heap: the buffer layers query millions of times. A pop
    // pushes two, so it never holds more than the tree's depth plus one, at most 34 (fewer
    // than 2^32 boxes, median splits down to leaf_size).
    std::size_t stack[64];
    std::size_t size = 0;
    stack[size++] = 0;
    while(size > 0) {
      const Node& n = m_nodes[stack[--size]];
      if(!CGAL::do_overlap(n.box, q)) continue;
      if(n.left == no_child) {
        for(std::size_t k = n.begin; k < n.end; ++k)
          if(CGAL::do_overlap(m_boxes[m_items[k]], q)) f(static_cast<std::size_t>(m_items[k]));
      } else {
        CGAL_assertion(size + 2 <= 64);
        stack[size++] = n.left;
        stack[size++] = n.right;
      }
    }
  }

private:
  static constexpr std::size_t leaf_size = 8;
  static constexpr std::size_t no_child = (std::numeric_limits<std::size_t>::max)();

  struct Node
  {
    Bbox_2 box;
    std::size_t begin, end, left, right;
  };

  std::size_t build(std::size_t begin, std::size_t end)
  {
    const std::size_t id = m_nodes.size();
    m_nodes.push_back(Node{Bbox_2(), begin, end, no_child, no_child});
    Bbox_2 box = m_boxes[m_items[begin]];
    double cx[2] = {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
    double cy[2] = {cx[0], cx[1]};
    for(std::size_t k = begin; k < end; ++k) {
      const Bbox_2& b = m_boxes[m_items[k]];
      box += b;
      const double x = 0.5 * (b.xmin() + b.xmax()), y = 0.5 * (b.ymin() + b.ymax());
      cx[0] = (std::min)(cx[0], x); cx[1] = (std::max)(cx[1], x);
      cy[0] = (std::min)(cy[0], y); cy[1] = (std::max)(cy[1], y);
    }
    m_nodes[id].box = box;
    if(end - begin <= leaf_size) return id;
    const bool split_x = (cx[1] - cx[0]) >= (cy[1] - cy[0]);
    const std::size_t mid = begin + (end - begin) / 2;
    std::nth_element(m_items.begin() + begin, m_items.begin() + mid, m_items.begin() + end,
                     [&](std::uint32_t a, std::uint32_t b) {
                       const Bbox_2& ba = m_boxes[a];
                       const Bbox_2& bb = m_boxes[b];
                       return split_x ? (ba.xmin() + ba.xmax()) < (bb.xmin() + bb.xmax())
                                      : (ba.ymin() + ba.ymax()) < (bb.ymin() + bb.ymax());
                     });
    const std::size_t l = build(begin, mid);
    const std::size_t r = build(mid, end);
    m_nodes[id].left = l;
    m_nodes[id].right = r;
    return id;
  }

  const std::vector<Bbox_2>& m_boxes;
  std::vector<std::uint32_t> m_items;
  std::vector<Node> m_nodes;
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_BOX_TREE_H
