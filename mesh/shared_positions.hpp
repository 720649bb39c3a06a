#pragma once
// A mesh's points, made once when it loads and then shared, read-only, by
// everything that renders it: the scene's mesh, its shadow caster and the
// silhouette arrays hold one array between them rather than a copy each. Reads
// like a const std::vector, and converts to one for functions that take it.

#include <initializer_list>
#include <memory>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

namespace umbra {

class SharedPositions {
 public:
  using Points = std::vector<glm::dvec3>;

  SharedPositions() : points_(no_points()) {}
  // Implicit, so that a vector of points (tests, generated meshes) passes
  // where shared positions are taken; the render path moves its one array in.
  SharedPositions(Points points) : points_(std::make_shared<const Points>(std::move(points))) {}
  SharedPositions(std::initializer_list<glm::dvec3> points) : SharedPositions(Points(points)) {}

  const Points& points() const { return *points_; }
  operator const Points&() const { return points(); }

  size_t size() const { return points().size(); }
  bool empty() const { return points().empty(); }
  const glm::dvec3& operator[](size_t i) const { return (*points_)[i]; }
  Points::const_iterator begin() const { return points().begin(); }
  Points::const_iterator end() const { return points().end(); }
  const glm::dvec3* data() const { return points().data(); }
  // Whether `other` is this very array, not an equal copy.
  bool same_array(const SharedPositions& other) const { return points_ == other.points_; }

 private:
  // Never null: an empty mesh shares one empty array.
  static const std::shared_ptr<const Points>& no_points() {
    static const std::shared_ptr<const Points> none = std::make_shared<const Points>();
    return none;
  }
  std::shared_ptr<const Points> points_;
};

}  // namespace umbra
