/*
 * sim_bridge's compiled laser kernel: many rays from one origin against boxes, cylinders,
 * spheres, planes and convex hulls, nearest hit per ray. Loaded with ctypes by sim_bridge.ray_kernel;
 * the numpy reference it must agree with is sim_bridge.ray_caster.
 *
 * A shape is one row of SBR_STRIDE doubles (the layout sim_bridge.ray_kernel packs):
 *   [0]      kind (SBR_BOX, SBR_CYLINDER, SBR_SPHERE, SBR_PLANE, SBR_HULL)
 *   [1..3]   centre in the world
 *   [4..12]  rotation, row-major (world <- shape)
 *   [13..15] box: half sizes; cylinder: radius, half length; sphere: radius; hull: its
 *            first plane's index in `planes` and how many it has
 *   [16]     bounding-sphere radius (planes: +inf, never culled)
 *
 * A hull's planes are rows of 4 doubles in the shape's frame, n_x n_y n_z d: an outward
 * unit normal n and an offset d, the hull being the points x with n.x <= d for every one
 * (a mesh's convex hull, sim_bridge.convex_hulls). They are fixed in the shape's frame, so
 * a moving hull is re-placed by its row alone.
 *
 * Distances are from the origin along unit directions; a surface counts from `near` to
 * `far` (a ray whose point at `near` is inside a shape reads `near`, as the reference does
 * when it starts its rays there). No hit: +inf.
 *
 * Why it is fast: shapes are taken in order of the nearest their bounding sphere comes to
 * the origin, so a ray stops looking once that exceeds its best hit; the origin is common
 * to all rays, so each shape's offset and the origin in its frame are worked out once per
 * call, not once per ray.
 */
#include <math.h>
#include <stdlib.h>

#define SBR_STRIDE 17
#define SBR_BOX 0
#define SBR_CYLINDER 1
#define SBR_SPHERE 2
#define SBR_PLANE 3
#define SBR_HULL 4
/* the calling convention's version: 2 added the planes of hulls (sbr_version) */
#define SBR_VERSION 2
/* a direction component smaller than this is parallel to a face (the reference's PARALLEL) */
#define SBR_PARALLEL 1e-12
/* a ray parallel to a face and this close outside its plane (m) touches it (the
 * reference's TOUCH: the same answer whatever the rounding) */
#define SBR_TOUCH 1e-9

typedef struct {
    double lo;        /* |centre - origin| - bound: no hit of this shape is nearer */
    double c[3];      /* centre - origin */
    double cc;        /* |c|^2 */
    double bound2;    /* bound^2 */
    double bound;
    double o[3];      /* the origin in the shape's frame */
    const double *row;
} Prepared;

static int by_lo(const void *a, const void *b) {
    double x = ((const Prepared *)a)->lo, y = ((const Prepared *)b)->lo;
    return (x > y) - (x < y);
}

/* Narrows [*t0, *t1] to where o + t d lies within |x| <= h along one axis; 0: empty. */
static int slab(double o, double d, double h, double *t0, double *t1) {
    if (fabs(d) < SBR_PARALLEL) {
        return fabs(o) <= h + SBR_TOUCH;
    }
    double inv = 1.0 / d;
    double a = (-h - o) * inv, b = (h - o) * inv;
    if (a > b) { double s = a; a = b; b = s; }
    if (a > *t0) *t0 = a;
    if (b < *t1) *t1 = b;
    return *t0 <= *t1;
}

/* Narrows [*t0, *t1] to where a t^2 + 2 b t + c <= 0 (a > 0); 0: empty. */
static int quadric(double a, double b, double c, double *t0, double *t1) {
    double disc = b * b - a * c;
    if (disc < 0.0) return 0;
    double root = sqrt(disc);
    double lo = (-b - root) / a, hi = (-b + root) / a;
    if (lo > *t0) *t0 = lo;
    if (hi < *t1) *t1 = hi;
    return *t0 <= *t1;
}

/* The interval of t (from the origin) during which the ray is inside the shape; 0: none. */
/* Narrows [*t0, *t1] to where o + t d is inside every plane n.x <= c (Cyrus-Beck); 0: empty.
 * A ray parallel to a plane is inside it all along or never, as a box's slab. */
static int clip(const double *plane, int count, const double *o, double dx, double dy,
                double dz, double *t0, double *t1) {
    for (int k = 0; k < count; ++k, plane += 4) {
        double rate = plane[0] * dx + plane[1] * dy + plane[2] * dz;
        double gap = plane[3] - (plane[0] * o[0] + plane[1] * o[1] + plane[2] * o[2]);
        if (fabs(rate) < SBR_PARALLEL) {
            if (gap < -SBR_TOUCH) return 0;
            continue;
        }
        double t = gap / rate;
        if (rate < 0.0) {
            if (t > *t0) *t0 = t;  /* entering through this plane */
        } else if (t < *t1) {
            *t1 = t;               /* leaving through it */
        }
        if (*t0 > *t1) return 0;
    }
    return 1;
}

static int inside_interval(const Prepared *p, const double *planes, const double *d,
                           double *t0, double *t1) {
    const double *r = p->row;
    /* the direction in the shape's frame: R^T d */
    double dx = r[4] * d[0] + r[7] * d[1] + r[10] * d[2];
    double dy = r[5] * d[0] + r[8] * d[1] + r[11] * d[2];
    double dz = r[6] * d[0] + r[9] * d[1] + r[12] * d[2];
    const double *o = p->o;
    *t0 = -INFINITY;
    *t1 = INFINITY;
    switch ((int)r[0]) {
    case SBR_BOX:
        return slab(o[0], dx, r[13], t0, t1) && slab(o[1], dy, r[14], t0, t1)
            && slab(o[2], dz, r[15], t0, t1);
    case SBR_CYLINDER: {
        double a = dx * dx + dy * dy;
        double c = o[0] * o[0] + o[1] * o[1] - r[13] * r[13];
        if (a < SBR_PARALLEL) {  /* along the axis: inside the circle or never */
            if (c > 0.0) return 0;
        } else if (!quadric(a, o[0] * dx + o[1] * dy, c, t0, t1)) {
            return 0;
        }
        return slab(o[2], dz, r[14], t0, t1);
    }
    case SBR_SPHERE:
        return quadric(1.0, o[0] * dx + o[1] * dy + o[2] * dz,
                       o[0] * o[0] + o[1] * o[1] + o[2] * o[2] - r[13] * r[13], t0, t1);
    case SBR_PLANE:  /* solid below local z = 0 */
        if (fabs(dz) < SBR_PARALLEL) return o[2] <= 0.0;
        if (dz < 0.0) *t0 = -o[2] / dz; else *t1 = -o[2] / dz;
        return *t0 <= *t1;
    case SBR_HULL:
        return clip(planes + 4 * (size_t)r[13], (int)r[14], o, dx, dy, dz, t0, t1);
    }
    return 0;
}

/*
 * Casts n_rays unit directions (n_rays x 3) from origin; out[i]: the distance from the
 * origin to the first surface within [near, far], +inf if none. `planes`: the hulls'
 * planes the rows index (may be NULL when no row is a hull). Returns 0, or -1 when
 * memory for the shapes' scratch could not be had.
 */
int sbr_cast(const double *shapes, int n_shapes, const double *planes, const double *origin,
             const double *dirs, int n_rays, double near, double far, double *out) {
    Prepared *prepared = malloc(sizeof(Prepared) * (n_shapes > 0 ? n_shapes : 1));
    if (prepared == NULL) return -1;
    int count = 0;
    for (int s = 0; s < n_shapes; ++s) {
        const double *r = shapes + (size_t)s * SBR_STRIDE;
        Prepared *p = &prepared[count];
        p->row = r;
        for (int k = 0; k < 3; ++k) p->c[k] = r[1 + k] - origin[k];
        p->cc = p->c[0] * p->c[0] + p->c[1] * p->c[1] + p->c[2] * p->c[2];
        p->bound = r[16];
        p->bound2 = r[16] * r[16];
        p->lo = sqrt(p->cc) - r[16];
        if (p->lo > far) continue;  /* out of range for every ray */
        /* origin in the shape's frame: R^T (origin - centre) = -R^T c */
        for (int k = 0; k < 3; ++k)
            p->o[k] = -(r[4 + k] * p->c[0] + r[7 + k] * p->c[1] + r[10 + k] * p->c[2]);
        ++count;
    }
    qsort(prepared, count, sizeof(Prepared), by_lo);
    for (int i = 0; i < n_rays; ++i) {
        const double *d = dirs + (size_t)i * 3;
        double best = INFINITY;
        for (int s = 0; s < count; ++s) {
            const Prepared *p = &prepared[s];
            if (p->lo > best) break;  /* this and every later shape is farther */
            if (isfinite(p->bound)) {
                double along = p->c[0] * d[0] + p->c[1] * d[1] + p->c[2] * d[2];
                if (along + p->bound < near) continue;          /* wholly behind near */
                if (p->cc - along * along > p->bound2) continue; /* passes beside it */
            }
            double t0, t1;
            if (!inside_interval(p, planes, d, &t0, &t1) || t1 < near) continue;
            double t = t0 > near ? t0 : near;
            if (t <= far && t < best) best = t;
        }
        out[i] = best;
    }
    free(prepared);
    return 0;
}

/* The row layout's width, so that the Python side can check it loaded a matching build. */
int sbr_stride(void) { return SBR_STRIDE; }

/* The calling convention's version, so that a build older than the Python side is told
 * to rebuild instead of being called with arguments it does not take. */
int sbr_version(void) { return SBR_VERSION; }
