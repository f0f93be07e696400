// One Kharaz impact at 20 degrees (talk's parameters, Model AA, dt = t_c/50) through the
// soft-sphere C ABI from C++, built against the installed package (find_package in
// CMakeLists.txt). Checks that the library it loaded is the one its header describes, then
// prints "angle e_t" as the Rust run does.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>

#include <soft_sphere.h>

namespace {

// A law owned as a C++ value: freed however the scope is left.
struct LawFree {
    void operator()(ss_law_f64 *law) const { ss_law_free_f64(law); }
};
using Law = std::unique_ptr<ss_law_f64, LawFree>;

constexpr double pi = 3.14159265358979323846;
constexpr double radius = 2.5e-3, density = 2700.0, speed = 3.9;

}  // namespace

int main() {
    if (std::strcmp(ss_version(), SS_VERSION_STRING) != 0) {
        std::fprintf(stderr, "library %s, header %s\n", ss_version(), SS_VERSION_STRING);
        return 1;
    }
    const int angle = 20;
    // The same arithmetic, in the same order, as the kernel's Sphere::solid.
    const double mass = (4.0 / 3.0) * pi * radius * radius * radius * density;
    ss_params_f64 params{};
    params.model = SS_MODEL_AA;
    params.normal_stiffness = 1000.0;
    params.restitution = 0.98;
    params.tangential_stiffness = 860.0;
    params.friction = 0.092;
    params.smallest_effective_mass = mass;
    double duration = 0.0;
    if (ss_contact_duration_f64(&params, mass, &duration) != SS_OK) return 2;
    params.time_step = duration / 50.0;
    ss_law_f64 *raw = nullptr;
    if (ss_law_new_f64(&params, &raw) != SS_OK) return 3;
    const Law law(raw);

    const double theta = angle * (pi / 180.0);
    ss_sphere_f64 sphere{};
    sphere.position = {0.0, 0.0, radius};
    sphere.velocity = {speed * std::sin(theta), 0.0, -speed * std::cos(theta)};
    sphere.radius = radius;
    sphere.mass = mass;
    ss_wall_f64 floor_wall{};
    floor_wall.direction = {0.0, 0.0, 1.0};
    ss_state_f64 state{};
    const ss_vec3_f64 zero{0.0, 0.0, 0.0};
    const double incoming = sphere.velocity.x;
    bool touched = false;
    for (;;) {
        ss_forces_f64 f{};
        if (ss_sphere_wall_f64(law.get(), &sphere, &floor_wall, &state, &f) != SS_OK) return 4;
        if (f.touching) {
            touched = true;
            ss_advance_sphere_f64(law.get(), &sphere, f.force_on_j, f.torque_on_j);
        } else if (touched) {
            break;
        } else {
            ss_advance_sphere_f64(law.get(), &sphere, zero, zero);
        }
    }
    std::printf("%2d %.15f\n", angle, sphere.velocity.x / incoming);
    return 0;
}
