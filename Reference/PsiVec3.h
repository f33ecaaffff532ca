// Three-vectors in double for the exact references and the tests' exact geometry.
#ifndef PsiVec3_h
#define PsiVec3_h

#include <array>

namespace psi
{
using Vec3 = std::array<double, 3>;

inline Vec3 Sub(const Vec3& a, const Vec3& b)
{
  return { { a[0] - b[0], a[1] - b[1], a[2] - b[2] } };
}

inline double Dot(const Vec3& a, const Vec3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

inline Vec3 Cross(const Vec3& a, const Vec3& b)
{
  return { { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] } };
}
} // namespace psi

#endif
