// Mass properties against closed forms: m = ρA, centroid, and I about the centre of mass.
//
// Expected values are computed in double from textbook formulas; the core sums a triangle fan
// in float. Summing n same-sign terms of a few float operations each is accurate to about
// 4·n·ε relative, so every comparison allows 16·n·ε (n = vertex count): tight enough that a
// wrong formula (a missing factor, the inertia about the wrong point) fails by orders of magnitude.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "perpdot/shapes.hpp"
#include "perpdot/world.hpp"
#include "physics_scenes.hpp"

namespace perpdot {
namespace {

using test::epsilon;

float tolerance(int n, double value) { return static_cast<float>(16.0 * n * epsilon * std::fabs(value)); }

// Closed-form area, centroid and second moment about the ORIGIN of a polygon (Green's theorem),
// independent of the core's fan about the vertex average.
struct PolygonMoments {
    double area = 0, cx = 0, cy = 0, originMoment = 0;
};

PolygonMoments greenMoments(const std::vector<Vec2>& p) {
    PolygonMoments g;
    const size_t n = p.size();
    for (size_t i = 0; i < n; ++i) {
        const double x0 = p[i].x, y0 = p[i].y, x1 = p[(i + 1) % n].x, y1 = p[(i + 1) % n].y;
        const double cross = x0 * y1 - x1 * y0;
        g.area += cross / 2;
        g.cx += (x0 + x1) * cross / 6;
        g.cy += (y0 + y1) * cross / 6;
        g.originMoment += cross * (x0 * x0 + x0 * x1 + x1 * x1 + y0 * y0 + y0 * y1 + y1 * y1) / 12;
    }
    g.cx /= g.area;
    g.cy /= g.area;
    return g;
}

TEST(Mass, CircleIsRhoPiRSquaredWithHalfMRSquared) {
    const double rho = 2.5, r = 0.75;
    const MassData md = computeMass(Circle{{1.0f, -2.0f}, 0.75f}, 2.5f);
    const double m = rho * std::numbers::pi * r * r;
    EXPECT_NEAR(md.mass, m, tolerance(1, m));
    EXPECT_NEAR(md.rotationalInertia, m * r * r / 2, tolerance(1, m * r * r / 2));
    EXPECT_EQ(md.center, (Vec2{1.0f, -2.0f}));
}

TEST(Mass, BoxIsMWSquaredPlusHSquaredOverTwelve) {
    const double rho = 3.0, w = 2.0, h = 0.5;
    const MassData md = computeMass(makeBox(1.0f, 0.25f), 3.0f);
    const double m = rho * w * h;
    EXPECT_NEAR(md.mass, m, tolerance(4, m));
    EXPECT_NEAR(md.rotationalInertia, m * (w * w + h * h) / 12, tolerance(4, m * (w * w + h * h) / 12));
    EXPECT_NEAR(md.center.x, 0.0f, tolerance(4, 1.0));
    EXPECT_NEAR(md.center.y, 0.0f, tolerance(4, 1.0));
}

TEST(Mass, TriangleUsesSideLengthsClosedForm) {
    // Right triangle with legs 3 and 4: A = 6, centroid = mean of vertices,
    // I_cm = m (a² + b² + c²) / 36 = m (9 + 16 + 25) / 36.
    const Vec2 pts[] = {{0, 0}, {3, 0}, {0, 4}};
    const MassData md = computeMass(makePolygon(pts), 2.0f);
    const double m = 2.0 * 6.0, I = m * 50.0 / 36.0;
    EXPECT_NEAR(md.mass, m, tolerance(3, m));
    EXPECT_NEAR(md.center.x, 1.0, tolerance(3, 1.0));
    EXPECT_NEAR(md.center.y, 4.0 / 3.0, tolerance(3, 4.0 / 3.0));
    EXPECT_NEAR(md.rotationalInertia, I, tolerance(3, I));
}

TEST(Mass, RegularPolygonsMatchTheNGonFormula) {
    // Regular n-gon with circumradius R: A = (n/2) R² sin(2π/n), I_cm = (m R²/6)(1 + 2 cos²(π/n)).
    const double R = 1.5, rho = 0.8;
    for (int n : {3, 5, 6, 8}) {
        std::vector<Vec2> pts;
        for (int k = 0; k < n; ++k) {
            const double a = 2 * std::numbers::pi * k / n;
            pts.push_back({static_cast<float>(R * std::cos(a)), static_cast<float>(R * std::sin(a))});
        }
        const MassData md = computeMass(makePolygon(pts), static_cast<float>(rho));
        const double m = rho * 0.5 * n * R * R * std::sin(2 * std::numbers::pi / n);
        const double c = std::cos(std::numbers::pi / n);
        const double I = m * R * R / 6 * (1 + 2 * c * c);
        EXPECT_NEAR(md.mass, m, tolerance(n, m)) << n << "-gon";
        EXPECT_NEAR(md.rotationalInertia, I, tolerance(n, I)) << n << "-gon";
        EXPECT_NEAR(md.center.x, 0.0, tolerance(n, R)) << n << "-gon";
        EXPECT_NEAR(md.center.y, 0.0, tolerance(n, R)) << n << "-gon";
    }
}

TEST(Mass, OffsetPolygonHasItsCentroidAndParallelAxisInertia) {
    // An irregular pentagon away from the origin: centroid from Green's theorem, and
    // I_cm = J_origin - m |c|² (parallel axis) with J_origin the second moment about the origin.
    const std::vector<Vec2> pts = {{3.0f, -2.0f}, {5.0f, -1.5f}, {5.5f, 0.5f}, {4.0f, 1.5f}, {2.5f, 0.0f}};
    const double rho = 1.7;
    const PolygonMoments g = greenMoments(pts);
    const MassData md = computeMass(makePolygon(pts), static_cast<float>(rho));
    const double m = rho * g.area;
    const double I = rho * g.originMoment - m * (g.cx * g.cx + g.cy * g.cy);
    EXPECT_NEAR(md.mass, m, tolerance(5, m));
    EXPECT_NEAR(md.center.x, g.cx, tolerance(5, g.cx));
    EXPECT_NEAR(md.center.y, g.cy, tolerance(5, std::fabs(g.cx)));
    EXPECT_NEAR(md.rotationalInertia, I, tolerance(5, I));
    // The parallel-axis term is much larger than I_cm here, so leaving it out could not pass.
    ASSERT_GT(m * (g.cx * g.cx + g.cy * g.cy), 10 * I);

    // A box moved to (3, -2) and turned: same I_cm as the centred box, centroid at the offset.
    const MassData box = computeMass(makeBox(1.0f, 0.25f, {3.0f, -2.0f}, 0.4f), 3.0f);
    const double mb = 3.0 * 2.0 * 0.5, Ib = mb * (4.0 + 0.25) / 12;
    EXPECT_NEAR(box.mass, mb, tolerance(4, mb));
    EXPECT_NEAR(box.center.x, 3.0, tolerance(4, 3.0));
    EXPECT_NEAR(box.center.y, -2.0, tolerance(4, 3.0));
    EXPECT_NEAR(box.rotationalInertia, Ib, tolerance(4, Ib));
}

TEST(Mass, RoundedBoxHasAreaPlusPerimeterTimesRPlusPiRSquared) {
    // A 2 x 1 box rounded by r: area A + P r + π r². Its inertia, built independently from the
    // core rectangle, four edge strips and four quarter discs, each moved to the origin (= centroid).
    const double hx = 1.0, hy = 0.5, r = 0.1, rho = 3.0;
    const Vec2 corners[] = {{-1.0f, -0.5f}, {1.0f, -0.5f}, {1.0f, 0.5f}, {-1.0f, 0.5f}};
    const MassData md = computeMass(makePolygon(corners, 0.1f), 3.0f);

    const double pi = std::numbers::pi;
    const double area = 4 * hx * hy + 4 * (hx + hy) * r + pi * r * r;
    auto rectangle = [](double w, double h, double cx, double cy) {  // ∫|p|² dA about the origin
        return w * h * ((w * w + h * h) / 12 + cx * cx + cy * cy);
    };
    // Quarter disc at corner C reaching outward: ∫|C + q|² = A|C|² + 2 C·(A q̄) + π r⁴/8, q̄ = 4r/(3π) per axis.
    const double quarter = pi * r * r / 4, reach = 4 * r / (3 * pi);
    const double cornerTerm = quarter * (hx * hx + hy * hy) + 2 * quarter * reach * (hx + hy) + pi * r * r * r * r / 8;
    const double J = rectangle(2 * hx, 2 * hy, 0, 0) + 2 * rectangle(2 * hx, r, 0, hy + r / 2) +
                     2 * rectangle(r, 2 * hy, hx + r / 2, 0) + 4 * cornerTerm;
    EXPECT_NEAR(md.mass, rho * area, tolerance(12, rho * area));
    EXPECT_NEAR(md.rotationalInertia, rho * J, tolerance(12, rho * J));
    EXPECT_NEAR(md.center.x, 0.0, tolerance(12, 1.0));
    EXPECT_NEAR(md.center.y, 0.0, tolerance(12, 1.0));
}

TEST(Mass, BodyWithTwoShapesCombinesWithTheParallelAxisTheorem) {
    // Box 1 x 0.5 at (-1, 0), ρ = 2, and a disc r = 0.4 at (1.5, 0.5), ρ = 5, on one body.
    World world;
    const BodyId body = world.createBody(test::bodyAt({1.0f, 2.0f}, BodyType::Dynamic, 0.3f));
    world.createShape(body, test::material(2.0f), makeBox(0.5f, 0.25f, {-1.0f, 0.0f}));
    const ShapeId disc = world.createShape(body, test::material(5.0f), Circle{{1.5f, 0.5f}, 0.4f});

    const double m1 = 2.0 * 1.0 * 0.5, I1 = m1 * (1.0 + 0.25) / 12, c1x = -1.0, c1y = 0.0;
    const double m2 = 5.0 * std::numbers::pi * 0.16, I2 = m2 * 0.16 / 2, c2x = 1.5, c2y = 0.5;
    const double m = m1 + m2, cx = (m1 * c1x + m2 * c2x) / m, cy = (m1 * c1y + m2 * c2y) / m;
    const double I = I1 + m1 * ((c1x - cx) * (c1x - cx) + (c1y - cy) * (c1y - cy)) + I2 +
                     m2 * ((c2x - cx) * (c2x - cx) + (c2y - cy) * (c2y - cy));
    EXPECT_NEAR(world.mass(body), m, tolerance(8, m));
    EXPECT_NEAR(world.localCenter(body).x, cx, tolerance(8, 1.5));
    EXPECT_NEAR(world.localCenter(body).y, cy, tolerance(8, 1.5));
    EXPECT_NEAR(world.rotationalInertia(body), I, tolerance(8, I));
    // The world centre is the local centre carried by the body frame.
    const Vec2 expectedCenter = transformPoint(world.transform(body), world.localCenter(body));
    EXPECT_NEAR(world.worldCenter(body).x, expectedCenter.x, tolerance(8, 3.0));
    EXPECT_NEAR(world.worldCenter(body).y, expectedCenter.y, tolerance(8, 3.0));

    // combineMass gives the same from the parts' own mass data.
    const MassData parts[] = {computeMass(makeBox(0.5f, 0.25f, {-1.0f, 0.0f}), 2.0f),
                              computeMass(Circle{{1.5f, 0.5f}, 0.4f}, 5.0f)};
    const MassData combined = combineMass(parts);
    EXPECT_NEAR(combined.mass, m, tolerance(8, m));
    EXPECT_NEAR(combined.rotationalInertia, I, tolerance(8, I));

    // Mass follows the shapes: without the disc the body is the box alone, about the box's centre.
    world.destroyShape(disc);
    EXPECT_NEAR(world.mass(body), m1, tolerance(4, m1));
    EXPECT_NEAR(world.localCenter(body).x, c1x, tolerance(4, 1.0));
    EXPECT_NEAR(world.rotationalInertia(body), I1, tolerance(4, I1));
}

}  // namespace
}  // namespace perpdot
