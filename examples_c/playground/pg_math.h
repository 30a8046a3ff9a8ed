/* Small vector helpers and the camera of the playground (header only, C99). z is up. */
#ifndef LFEM_PLAYGROUND_MATH_H
#define LFEM_PLAYGROUND_MATH_H

#include <math.h>

#define PG_PI 3.14159265358979323846

static inline void v3_set(double out[3], double x, double y, double z) {
    out[0] = x, out[1] = y, out[2] = z;
}
static inline void v3_sub(const double a[3], const double b[3], double out[3]) {
    for (int i = 0; i < 3; ++i) out[i] = a[i] - b[i];
}
static inline void v3_add_scaled(const double a[3], double s, const double b[3], double out[3]) {
    for (int i = 0; i < 3; ++i) out[i] = a[i] + s * b[i];
}
static inline double v3_dot(const double a[3], const double b[3]) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
static inline void v3_cross(const double a[3], const double b[3], double out[3]) {
    const double x = a[1] * b[2] - a[2] * b[1], y = a[2] * b[0] - a[0] * b[2],
                 z = a[0] * b[1] - a[1] * b[0];
    out[0] = x, out[1] = y, out[2] = z;
}
static inline double v3_length(const double a[3]) { return sqrt(v3_dot(a, a)); }
static inline void v3_normalize(double a[3]) {
    const double n = v3_length(a);
    if (n > 0) a[0] /= n, a[1] /= n, a[2] /= n;
}

/* Rotate v by the unit quaternion q = (w, x, y, z). */
static inline void quat_rotate(const double q[4], const double v[3], double out[3]) {
    const double u[3] = {q[1], q[2], q[3]};
    double t[3], ut[3];
    v3_cross(u, v, t);
    for (int i = 0; i < 3; ++i) t[i] *= 2;
    v3_cross(u, t, ut);
    for (int i = 0; i < 3; ++i) out[i] = v[i] + q[0] * t[i] + ut[i];
}

/* An orbit camera: it looks at target from distance, turned by yaw about z and pitched up. */
typedef struct pg_camera {
    double target[3];
    double distance, yaw, pitch; /* m, rad, rad */
    double fov_y;                /* rad */
    int width, height;           /* the viewport, pixels */
} pg_camera;

/* Where the eye is and the camera's unit axes: forward (into the screen), right, up. */
static inline void camera_frame(const pg_camera* c, double eye[3], double forward[3],
                                double right[3], double up[3]) {
    v3_set(forward, cos(c->pitch) * sin(c->yaw), cos(c->pitch) * cos(c->yaw), -sin(c->pitch));
    v3_add_scaled(c->target, -c->distance, forward, eye);
    const double z[3] = {0, 0, 1};
    v3_cross(forward, z, right);
    v3_normalize(right);
    v3_cross(right, forward, up);
}

/* The ray from the eye through the centre of pixel (px, py) (x right, y down): the mouse's. */
static inline void camera_ray(const pg_camera* c, double px, double py, double origin[3],
                              double direction[3]) {
    double forward[3], right[3], up[3];
    camera_frame(c, origin, forward, right, up);
    const double t = tan(0.5 * c->fov_y), aspect = (double)c->width / c->height;
    const double sx = (2 * (px + 0.5) / c->width - 1) * t * aspect;
    const double sy = (1 - 2 * (py + 0.5) / c->height) * t;
    for (int i = 0; i < 3; ++i) direction[i] = forward[i] + sx * right[i] + sy * up[i];
    v3_normalize(direction);
}

/* The pixel a world point projects to (the inverse of camera_ray); 0 when behind the eye. */
static inline int camera_project(const pg_camera* c, const double p[3], double* px, double* py) {
    double eye[3], forward[3], right[3], up[3], d[3];
    camera_frame(c, eye, forward, right, up);
    v3_sub(p, eye, d);
    const double depth = v3_dot(d, forward);
    if (depth <= 0) return 0;
    const double t = tan(0.5 * c->fov_y), aspect = (double)c->width / c->height;
    *px = (v3_dot(d, right) / depth / (t * aspect) + 1) * 0.5 * c->width - 0.5;
    *py = (1 - v3_dot(d, up) / depth / t) * 0.5 * c->height - 0.5;
    return 1;
}

#endif
