// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A small static bounding-volume hierarchy of boxes, for the simultaneous (two-tree)
// traversal of the collision-detection filter (cd_filter.h). CGAL's AABB_tree does not
// expose its nodes, and the filter needs to walk two trees at once.
//
// Flat arrays, built once by median splits along the longest axis of the boxes' centres,
// read concurrently afterwards. Every box is the exact union of the double boxes of its
// items (no rounding: min and max of doubles), so a node box contains the box of every item
// below it.

#ifndef CGAL_PMSUM_INTERNAL_BVH_H
#define CGAL_PMSUM_INTERNAL_BVH_H

#include <CGAL/Bbox_3.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Pmsum {
namespace internal {

class Bvh
{
public:
  static constexpr std::uint32_t leaf_size = 4;

  struct Node
  {
    CGAL::Bbox_3 box;
    std::uint32_t first, count; // leaf: items [first, first + count) of item(); inner: count == 0
    std::uint32_t right;        // inner: the right child (the left one is the next node)
    bool is_leaf() const { return count > 0; }
  };

  Bvh() = default;

  /// Builds the hierarchy of `boxes`; item k of a leaf is boxes[item(k)].
  explicit Bvh(const std::vector<CGAL::Bbox_3>& boxes)
  {
    if (boxes.empty()) return;
    m_items.resize(boxes.size());
    for (std::uint32_t i = 0; i < m_items.size(); ++i) m_items[i] = i;
    m_nodes.reserve(2 * boxes.size() / leaf_size + 2);
    build(boxes, 0, static_cast<std::uint32_t>(boxes.size()));
    for (std::uint32_t k : m_items) m_item_boxes.push_back(boxes[k]);
  }

  bool empty() const { return m_nodes.empty(); }
  const Node& node(std::uint32_t i) const { return m_nodes[i]; }
  const Node& root() const { return m_nodes[0]; }
  std::uint32_t item(std::uint32_t k) const { return m_items[k]; }
  const CGAL::Bbox_3& item_box(std::uint32_t k) const { return m_item_boxes[k]; } // box of item(k)

private:
  std::uint32_t build(const std::vector<CGAL::Bbox_3>& boxes, std::uint32_t first, std::uint32_t last)
  {
    const std::uint32_t index = static_cast<std::uint32_t>(m_nodes.size());
    m_nodes.push_back(Node{CGAL::Bbox_3(), first, last - first, 0});
    CGAL::Bbox_3 box = boxes[m_items[first]];
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (std::uint32_t k = first; k < last; ++k) {
      const CGAL::Bbox_3& b = boxes[m_items[k]];
      box += b;
      for (int c = 0; c < 3; ++c) {
        lo[c] = (std::min)(lo[c], b.min(c) + b.max(c));
        hi[c] = (std::max)(hi[c], b.min(c) + b.max(c));
      }
    }
    m_nodes[index].box = box;
    if (last - first <= leaf_size) return index;
    int axis = 0;
    for (int c = 1; c < 3; ++c)
      if (hi[c] - lo[c] > hi[axis] - lo[axis]) axis = c;
    // Median split by (twice) the centre; ties broken by index, so the tree is deterministic.
    const std::uint32_t mid = first + (last - first) / 2;
    std::nth_element(m_items.begin() + first, m_items.begin() + mid, m_items.begin() + last,
                     [&](std::uint32_t a, std::uint32_t b) {
                       const double ca = boxes[a].min(axis) + boxes[a].max(axis);
                       const double cb = boxes[b].min(axis) + boxes[b].max(axis);
                       return ca < cb || (ca == cb && a < b);
                     });
    m_nodes[index].count = 0;
    build(boxes, first, mid);
    const std::uint32_t right = build(boxes, mid, last);
    m_nodes[index].right = right;
    return index;
  }

  std::vector<Node> m_nodes;
  std::vector<std::uint32_t> m_items;
  std::vector<CGAL::Bbox_3> m_item_boxes;
};

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_BVH_H
