// Mirror reflection, Snell refraction and total internal reflection.
#include "catch.h"

#include "pathlab/lab.h"
#include "pathlab/render/specular.h"

using namespace pathlab;

namespace {
Hit hitOn(const Vec3& normal, bool frontFace, float ni) {
    Hit hit;
    hit.found = true;
    hit.normal = hit.geometricNormal = normal;
    hit.frontFace = frontFace;
    hit.material.Ni = ni;
    return hit;
}
} // namespace

TEST_CASE("reflect mirrors the direction about the normal", "[sampling][specular]") {
    const Vec3 d = normalize(Vec3{1, -1, 0});
    const Vec3 r = reflect(d, Vec3{0, 1, 0});
    CHECK(r.x == Approx(d.x));
    CHECK(r.y == Approx(-d.y));
    CHECK(r.z == Approx(0.0f).margin(1e-7));
}

TEST_CASE("refract obeys Snell's law, both ways", "[sampling][specular]") {
    const float thetaIn = 0.6f; // radians from the normal
    const Vec3 d{std::sin(thetaIn), -std::cos(thetaIn), 0};
    const Vec3 n{0, 1, 0};
    const auto t = refract(d, n, 1.0f / 1.5f);
    REQUIRE(t);
    const float sinOut = t->x; // tangential component of a unit vector
    CHECK(1.0f * std::sin(thetaIn) == Approx(1.5f * sinOut).epsilon(1e-5));
    CHECK(t->y < 0); // carries on through the surface
    CHECK(length(*t) == Approx(1.0f).epsilon(1e-6));

    // And back out of the glass along the same line, reversed.
    const auto back = refract(-*t, n * -1.0f, 1.5f);
    REQUIRE(back);
    CHECK(back->x == Approx(-d.x).epsilon(1e-5));
    CHECK(back->y == Approx(-d.y).epsilon(1e-5));
}

TEST_CASE("beyond the critical angle there is total internal reflection", "[sampling][specular]") {
    // Leaving glass (n=1.5) the critical angle is asin(1/1.5) = 41.8°.
    const Vec3 n{0, 1, 0};
    const float below = 0.70f, above = 0.75f; // radians: 40.1° and 43.0°
    CHECK(refract({std::sin(below), -std::cos(below), 0}, n, 1.5f).has_value());
    CHECK_FALSE(refract({std::sin(above), -std::cos(above), 0}, n, 1.5f).has_value());
}

TEST_CASE("refractionRay falls back to the mirror ray under total internal reflection",
          "[sampling][specular]") {
    const float angle = 0.9f; // 51.6°, beyond the critical angle inside glass
    const Ray inside{{0, 0, 0}, {std::sin(angle), -std::cos(angle), 0}, RayKind::Specular};
    // The ray meets the glass surface from inside: the back face, normal turned toward it.
    const Hit hit = hitOn({0, 1, 0}, /*frontFace=*/false, 1.5f);
    const Ray out = refractionRay(inside, hit);
    const Ray mirror = mirrorRay(inside, hit);
    CHECK(out.direction.x == Approx(mirror.direction.x));
    CHECK(out.direction.y == Approx(mirror.direction.y));
    CHECK(out.direction.y > 0);
    CHECK(out.kind == RayKind::Specular);

    // Entering from outside at the same angle always refracts, bending toward the normal.
    const Hit front = hitOn({0, 1, 0}, /*frontFace=*/true, 1.5f);
    const Ray in = refractionRay(inside, front);
    CHECK(in.direction.y < 0);
    CHECK(std::fabs(in.direction.x) < std::sin(angle));
}

TEST_CASE("bounce rays start just off the surface, on the side they leave by",
          "[sampling][specular]") {
    Hit hit = hitOn({0, 1, 0}, true, 1.0f);
    hit.position = {100, 0, 0};
    const Ray up = mirrorRay({{100, 1, -1}, normalize(Vec3{0, -1, 1}), RayKind::Camera}, hit);
    CHECK(up.origin.y > 0);
    CHECK(up.origin.y < 0.01f);
    const Ray diffuse = diffuseRay(hit, {0.3f, 0.6f});
    CHECK(diffuse.kind == RayKind::Diffuse);
    CHECK(dot(diffuse.direction, hit.normal) > 0);
}
