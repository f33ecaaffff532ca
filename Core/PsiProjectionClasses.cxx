#include "PsiProjectionClasses.h"

#include <sstream>

namespace psi
{
namespace
{
int Sign(double v)
{
  return (v > 0) - (v < 0);
}

// Twice the signed area of triangle (a, b, c).
double Orient(const double x[4], const double y[4], int a, int b, int c)
{
  return (x[b] - x[a]) * (y[c] - y[a]) - (y[b] - y[a]) * (x[c] - x[a]);
}

bool Same(const double x[4], const double y[4], int a, int b)
{
  return x[a] == x[b] && y[a] == y[b];
}

// True when c lies strictly between a and b on their common line (a, b, c collinear).
bool Between(const double x[4], const double y[4], int a, int b, int c)
{
  const double d = (x[c] - x[a]) * (x[b] - x[a]) + (y[c] - y[a]) * (y[b] - y[a]);
  const double l = (x[b] - x[a]) * (x[b] - x[a]) + (y[b] - y[a]) * (y[b] - y[a]);
  return d > 0 && d < l;
}

// Proper crossing of segments ab and cd (no three of the points collinear).
bool Cross(const double x[4], const double y[4], int a, int b, int c, int d)
{
  return Sign(Orient(x, y, a, b, c)) * Sign(Orient(x, y, a, b, d)) < 0 &&
    Sign(Orient(x, y, c, d, a)) * Sign(Orient(x, y, c, d, b)) < 0;
}

bool Inside(const double x[4], const double y[4], int a, int b, int c, int m)
{
  const int s1 = Sign(Orient(x, y, a, b, m));
  const int s2 = Sign(Orient(x, y, b, c, m));
  const int s3 = Sign(Orient(x, y, c, a, m));
  return s1 != 0 && s1 == s2 && s2 == s3;
}
} // namespace

int TruthTableIndex(const double x[4], const double y[4])
{
  // Marroquim et al. 2006, Fig. 3. (v1-v2) x (v1-v3) equals (v2-v1) x (v3-v1), i.e. Orient(1,2,3).
  const int t1 = Sign(Orient(x, y, 0, 1, 2)) + 1;
  const int t2 = Sign(Orient(x, y, 0, 1, 3)) + 1;
  const int t3 = Sign(Orient(x, y, 0, 2, 3)) + 1;
  const int t4 = Sign(Orient(x, y, 1, 2, 3)) + 1;
  return 27 * t1 + 9 * t2 + 3 * t3 + t4;
}

ProjectionClass ClassifyProjection(const double x[4], const double y[4])
{
  ProjectionClass r;
  // Coincident pairs -> class 4 (exactly one pair, the rest not collinear with it).
  int pairs = 0;
  int pa = -1, pb = -1;
  for (int i = 0; i < 4; ++i)
  {
    for (int j = i + 1; j < 4; ++j)
    {
      if (Same(x, y, i, j))
      {
        ++pairs;
        pa = i;
        pb = j;
      }
    }
  }
  if (pairs > 1)
  {
    return r; // three or more coincide, or two coincident pairs: a line at best
  }
  if (pairs == 1)
  {
    int o[2], n = 0;
    for (int k = 0; k < 4; ++k)
    {
      if (k != pa && k != pb)
      {
        o[n++] = k;
      }
    }
    if (Orient(x, y, pa, o[0], o[1]) == 0)
    {
      return r; // all on one line
    }
    r.cls = 4;
    r.p = { { o[0], o[1], pa, pb } };
    return r;
  }
  // One collinear triple -> class 3 (its middle vertex lies on the edge of the other two).
  static const int triples[4][4] = { { 0, 1, 2, 3 }, { 0, 1, 3, 2 }, { 0, 2, 3, 1 },
    { 1, 2, 3, 0 } };
  int collinear = 0;
  for (const auto& t : triples)
  {
    if (Orient(x, y, t[0], t[1], t[2]) == 0)
    {
      ++collinear;
      const int a = t[0], b = t[1], c = t[2];
      if (Between(x, y, a, b, c))
      {
        r.p = { { a, b, t[3], c } };
      }
      else if (Between(x, y, a, c, b))
      {
        r.p = { { a, c, t[3], b } };
      }
      else
      {
        r.p = { { b, c, t[3], a } };
      }
    }
  }
  if (collinear > 1)
  {
    return ProjectionClass{}; // all four collinear
  }
  if (collinear == 1)
  {
    r.cls = 3;
    return r;
  }
  // General position: a vertex inside the others' triangle (class 1) or crossing edges (class 2).
  static const int inner[4][4] = { { 1, 2, 3, 0 }, { 0, 2, 3, 1 }, { 0, 1, 3, 2 }, { 0, 1, 2, 3 } };
  for (const auto& t : inner)
  {
    if (Inside(x, y, t[0], t[1], t[2], t[3]))
    {
      r.cls = 1;
      r.p = { { t[0], t[1], t[2], t[3] } };
      return r;
    }
  }
  static const int diag[3][4] = { { 0, 1, 2, 3 }, { 0, 2, 1, 3 }, { 0, 3, 1, 2 } };
  for (const auto& t : diag)
  {
    if (Cross(x, y, t[0], t[1], t[2], t[3]))
    {
      r.cls = 2;
      r.p = { { t[0], t[1], t[2], t[3] } };
      return r;
    }
  }
  return ProjectionClass{}; // unreachable for four points in general position
}

bool BuildProjectionClassTable(ProjectionClassTable& table, std::string* error)
{
  std::array<bool, 81> seen{};
  table.fill(ProjectionClass{});
  // A 5x5 lattice realizes every sign pattern that four points can have (tested: all 81 - 0-class
  // patterns are reached; a larger lattice adds none).
  constexpr int R = 2;
  double x[4], y[4];
  const int n = 2 * R + 1;
  const int total = n * n * n * n * n * n * n * n;
  for (int code = 0; code < total; ++code)
  {
    int c = code;
    for (int i = 0; i < 4; ++i)
    {
      x[i] = c % n - R;
      c /= n;
      y[i] = c % n - R;
      c /= n;
    }
    const int idx = TruthTableIndex(x, y);
    const ProjectionClass pc = ClassifyProjection(x, y);
    if (!seen[idx])
    {
      seen[idx] = true;
      table[idx] = pc;
      continue;
    }
    // Same sign pattern must mean the same class and the same roles (for class 1 and 2 the
    // silhouette order may differ, which does not change the rendered fan).
    const ProjectionClass& t = table[idx];
    bool same = t.cls == pc.cls;
    if (same && pc.cls == 1)
    {
      same = t.p[3] == pc.p[3];
    }
    else if (same && pc.cls == 2)
    {
      const bool d1 =
        (t.p[0] == pc.p[0] && t.p[1] == pc.p[1]) || (t.p[0] == pc.p[1] && t.p[1] == pc.p[0]);
      const bool d2 =
        (t.p[0] == pc.p[2] && t.p[1] == pc.p[3]) || (t.p[0] == pc.p[3] && t.p[1] == pc.p[2]);
      same = d1 || d2;
    }
    else if (same && pc.cls == 3)
    {
      same = t.p[3] == pc.p[3] && t.p[2] == pc.p[2];
    }
    else if (same && pc.cls == 4)
    {
      same = (t.p[2] == pc.p[2] && t.p[3] == pc.p[3]);
    }
    if (!same)
    {
      if (error)
      {
        std::ostringstream os;
        os << "sign pattern " << idx << " classified as " << t.cls << " and " << pc.cls;
        *error = os.str();
      }
      return false;
    }
  }
  return true;
}

const ProjectionClassTable& GetProjectionClassTable()
{
  static const ProjectionClassTable table = []
  {
    ProjectionClassTable t;
    BuildProjectionClassTable(t);
    return t;
  }();
  return table;
}

int PackProjectionClass(const ProjectionClass& c)
{
  return c.cls | (c.p[0] << 4) | (c.p[1] << 6) | (c.p[2] << 8) | (c.p[3] << 10);
}

const std::array<int, 81>& GetPackedProjectionClassTable()
{
  static const std::array<int, 81> packed = []
  {
    std::array<int, 81> p{};
    for (int i = 0; i < 81; ++i)
    {
      p[i] = PackProjectionClass(GetProjectionClassTable()[i]);
    }
    return p;
  }();
  return packed;
}

} // namespace psi
