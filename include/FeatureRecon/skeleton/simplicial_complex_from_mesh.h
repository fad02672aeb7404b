// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (c) 2026 The FeatureRecon authors.
#ifndef FEATURERECON_SKELETON_SIMPLICIAL_COMPLEX_FROM_MESH_H
#define FEATURERECON_SKELETON_SIMPLICIAL_COMPLEX_FROM_MESH_H

#include <FeatureRecon/assertions.h>
#include <FeatureRecon/skeleton/Augmented_reeb_graph.h>
#include <FeatureRecon/skeleton/Simplicial_complex_2.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <type_traits>
#include <vector>

namespace FeatureRecon {
namespace skeleton {

/// The simplicial 2-complex of a triangle mesh (any model of CGAL's `FaceListGraph`, e.g.
/// `CGAL::Surface_mesh` or `CGAL::Polyhedron_3`): vertex i of the complex is the mesh vertex with index i
/// in CGAL's initialized vertex index map (`v.idx()` for a Surface_mesh without removed elements).
/// \pre every face is a triangle (checked; throws naming the face's index and size: triangulate first,
///      e.g. with CGAL::Polygon_mesh_processing::triangulate_faces()); the vertex indices are 0 .. n-1 for
///      the n vertices (checked; throws: a Surface_mesh with removed elements needs collect_garbage() first).
template <class FaceGraph>
Simplicial_complex_2 simplicial_complex_from_mesh(const FaceGraph& mesh) {
  const char* fn = "simplicial_complex_from_mesh";
  const auto vindex = CGAL::get_initialized_vertex_index_map(mesh);
  // The indices must be 0 .. n-1 for the n vertices the mesh has (a Surface_mesh with removed but not
  // collected vertices has gaps: each would become an isolated vertex of the complex).
  std::size_t live = 0;
  for (auto v : vertices(mesh)) {
    (void)v;
    ++live;
  }
  for (auto v : vertices(mesh))
    if (static_cast<std::size_t>(get(vindex, v)) >= live)
      FeatureRecon::internal::throw_invalid_argument(fn, "vertex index ", get(vindex, v),
                                                     " is not below the ", live,
                                                     " vertices of the mesh (removed elements? call "
                                                     "collect_garbage() first)");
  std::vector<Edge> edges_out;
  std::vector<Triangle> triangles_out;
  for (auto e : edges(mesh)) {
    const auto h = halfedge(e, mesh);
    edges_out.push_back({static_cast<Vertex_index>(get(vindex, source(h, mesh))),
                         static_cast<Vertex_index>(get(vindex, target(h, mesh)))});
  }
  std::size_t face_number = 0;
  for (auto f : faces(mesh)) {
    std::vector<Vertex_index> vs;
    for (auto v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
      vs.push_back(static_cast<Vertex_index>(get(vindex, v)));
    if (vs.size() != 3)
      FeatureRecon::internal::throw_invalid_argument(fn, "face ", face_number, " has ", vs.size(),
                                                     " vertices; triangulate the mesh first");
    triangles_out.push_back({vs[0], vs[1], vs[2]});
    ++face_number;
  }
  return make_simplicial_complex_2(live, std::move(edges_out), std::move(triangles_out));
}

/// Augmented Reeb graph of a function given by a vertex property map on a triangle mesh
/// (simplicial_complex_from_mesh() then compute_augmented_reeb_graph()). Node i is the vertex of index i.
/// \pre as simplicial_complex_from_mesh(); every value finite (checked; throws naming the vertex index).
template <class FaceGraph, class VertexValueMap>
Augmented_reeb_graph compute_augmented_reeb_graph(const FaceGraph& mesh, VertexValueMap f,
                                                  const Reeb_graph_options& options = {}) {
  // A Proximity_graph (not a complex) would match here and fail deep inside CGAL's BGL code: one message.
  constexpr bool is_graph_not_complex = std::is_base_of<Proximity_graph, FaceGraph>::value &&
                                        !std::is_same<FaceGraph, Simplicial_complex_2>::value;
  static_assert(
      !is_graph_not_complex,
      "FeatureRecon: compute_augmented_reeb_graph() takes a Simplicial_complex_2 with a range of values, "
      "or a triangle mesh with a vertex property map; a Proximity_graph has no triangles: pass "
      "build_flag_complex_2(graph), the Rips 2-complex of a Rips graph");
  if constexpr (is_graph_not_complex) {
    return compute_augmented_reeb_graph(Simplicial_complex_2(), std::vector<double>(), options);
  } else {
    const Simplicial_complex_2 k = simplicial_complex_from_mesh(mesh);
    const auto vindex = CGAL::get_initialized_vertex_index_map(mesh);
    std::vector<double> values(k.number_of_vertices, 0.0);
    for (auto v : vertices(mesh)) values[get(vindex, v)] = static_cast<double>(get(f, v));
    return compute_augmented_reeb_graph(k, values, options);
  }
}

}  // namespace skeleton
}  // namespace FeatureRecon

#endif  // FEATURERECON_SKELETON_SIMPLICIAL_COMPLEX_FROM_MESH_H
