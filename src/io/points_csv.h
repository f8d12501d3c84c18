// POINTS.csv for `vlit probe`: header px,py,pz,nx,ny,nz,ex,ey,ez,m then one point per row.
#pragma once

#include <string>
#include <vector>

#include "core/vec3.h"

namespace vlit {

struct ProbePoint {
  Vec3d position;
  Vec3d normal;     // as written; normalized by the caller
  Vec3d eye;
  double shininess = 1;
};

// Throws InputError naming the file and line for a bad header, a bad number, a wrong column
// count, a zero normal or a negative shininess.
std::vector<ProbePoint> parse_points_csv(const std::string& text, const std::string& name);
std::vector<ProbePoint> read_points_csv(const std::string& path);

}  // namespace vlit
