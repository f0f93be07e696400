/* The Kharaz oblique-impact sweep (talk's parameters, Model AA, dt = t_c/50) through the
 * soft-sphere C ABI: the host owns the sphere, the per-contact state and the loop.
 * Prints "angle e_t" per line, angles 1 to 89 degrees. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "soft_sphere.h"

static const double RADIUS = 2.5e-3, DENSITY = 2700.0, SPEED = 3.9;

static int tangential_restitution(int angle_deg, double *e_t) {
    const double pi = 3.14159265358979323846;
    /* The same arithmetic, in the same order, as the kernel's Sphere::solid. */
    double mass = (4.0 / 3.0) * pi * RADIUS * RADIUS * RADIUS * DENSITY;
    ss_params_f64 params = {
        .model = SS_MODEL_AA, .normal_stiffness = 1000.0, .restitution = 0.98,
        .tangential_stiffness = 860.0, .dashpot_ratio = 0.0, .friction = 0.092,
        .smallest_effective_mass = mass,
    };
    double duration;
    int code = ss_contact_duration_f64(&params, mass, &duration);
    if (code != SS_OK) return code;
    params.time_step = duration / 50.0;
    ss_law_f64 *law = NULL;
    if ((code = ss_law_new_f64(&params, &law)) != SS_OK) return code;

    double theta = angle_deg * (pi / 180.0);
    ss_sphere_f64 sphere = {
        .position = {0.0, 0.0, RADIUS},
        .velocity = {SPEED * sin(theta), 0.0, -SPEED * cos(theta)},
        .radius = RADIUS, .mass = mass,
    };
    ss_wall_f64 floor_wall = {.point = {0, 0, 0}, .direction = {0, 0, 1}};
    ss_state_f64 state = {.displacement = {0, 0, 0}};
    ss_vec3_f64 zero = {0, 0, 0};
    double incoming = sphere.velocity.x;
    int touched = 0;
    for (;;) {
        ss_forces_f64 f;
        if ((code = ss_sphere_wall_f64(law, &sphere, &floor_wall, &state, &f)) != SS_OK) break;
        if (f.touching) {
            touched = 1;
            ss_advance_sphere_f64(law, &sphere, f.force_on_j, f.torque_on_j);
        } else if (touched) {
            *e_t = sphere.velocity.x / incoming;
            break;
        } else {
            ss_advance_sphere_f64(law, &sphere, zero, zero);
        }
    }
    ss_law_free_f64(law);
    return code;
}

int main(int argc, char **argv) {
    (void)argv;
    /* The library loaded is the one this header describes. */
    if (strcmp(ss_version(), SS_VERSION_STRING) != 0) {
        fprintf(stderr, "library %s, header %s\n", ss_version(), SS_VERSION_STRING);
        return 1;
    }
    /* A bad parameter is an error code, not a crash. */
    ss_params_f64 bad = {.model = SS_MODEL_AA, .normal_stiffness = -1.0};
    ss_law_f64 *none = NULL;
    if (ss_law_new_f64(&bad, &none) != SS_ERR_NOT_POSITIVE || none != NULL) {
        fprintf(stderr, "bad parameters were not rejected\n");
        return 1;
    }
    for (int angle = 1; angle <= 89; ++angle) {
        double e_t = 0.0;
        int code = tangential_restitution(angle, &e_t);
        if (code != SS_OK) {
            fprintf(stderr, "angle %d: error %d\n", angle, code);
            return 1;
        }
        printf("%2d %.15f\n", angle, e_t);
    }
    return argc > 1 ? 0 : 0;
}
