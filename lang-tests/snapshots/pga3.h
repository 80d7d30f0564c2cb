/* pga3: Motor=even;Point=grade3;Line=grade2; ops gp,apply,apply_unit,reverse,norm_squared,exp,log_unit,normalize */
#ifndef GAM_PGA3_H
#define GAM_PGA3_H

/* Motor: the coefficients of scalar, e01, e02, e12, e03, e13, e23, e0123. */
typedef struct pga3_Motor {
    double scalar;
    double e01;
    double e02;
    double e12;
    double e03;
    double e13;
    double e23;
    double e0123;
} pga3_Motor;

/* Point: the coefficients of e012, e013, e023, e123. */
typedef struct pga3_Point {
    double e012;
    double e013;
    double e023;
    double e123;
} pga3_Point;

/* Line: the coefficients of e01, e02, e12, e03, e13, e23. */
typedef struct pga3_Line {
    double e01;
    double e02;
    double e12;
    double e03;
    double e13;
    double e23;
} pga3_Line;

/* The odd part of the algebra, declared automatically: some product of the declared types lands here. */
/* Odd: the coefficients of e0, e1, e2, e3, e012, e013, e023, e123. */
typedef struct pga3_Odd {
    double e0;
    double e1;
    double e2;
    double e3;
    double e012;
    double e013;
    double e023;
    double e123;
} pga3_Odd;

#include <math.h>

typedef struct pga3_Triple {
    double x, y, z;
} pga3_Triple;

/* (sinc t, (cos t - sinc t) / t^2, cos t) from t^2 >= 0 (series below t = 1e-3). */
static inline pga3_Triple pga3_exp_factors(double theta2) {
    const double theta = sqrt(theta2);
    if (theta < 0.001) {
        const double t4 = theta2 * theta2;
        { pga3_Triple out; out.x = (1.0 - 0.16666666666666666 * theta2) + 0.008333333333333333 * t4; out.y = ((-0.3333333333333333) + 0.03333333333333333 * theta2) - 0.0011904761904761906 * t4; out.z = (1.0 - 0.5 * theta2) + 0.041666666666666664 * t4; return out; }
    } else {
        const double si = sin(theta);
        const double co = cos(theta);
        const double inv = 1.0 / theta;
        const double sinc = si * inv;
        { pga3_Triple out; out.x = sinc; out.y = (co - sinc) * (inv * inv); out.z = co; return out; }
    }
}

/* (t / sin t, (t cos t - sin t) / sin^3 t, 0) from sin t >= 0 and cos t, t = atan2 (series below t = 1e-3). */
static inline pga3_Triple pga3_log_factors(double si, double co) {
    const double theta = atan2(si, co);
    if (theta < 0.001) {
        const double t2 = theta * theta;
        const double t4 = t2 * t2;
        { pga3_Triple out; out.x = (1.0 + 0.16666666666666666 * t2) + 0.019444444444444445 * t4; out.y = ((-0.3333333333333333) - 0.13333333333333333 * t2) - 0.031746031746031744 * t4; out.z = 0.0; return out; }
    } else {
        const double r = 1.0 / si;
        const double r2 = r * r;
        { pga3_Triple out; out.x = theta * r; out.y = (theta * co - si) * (r2 * r); out.z = 0.0; return out; }
    }
}

/* `gp` of a Motor and a Motor. */
static inline pga3_Motor pga3_motor_gp_motor(pga3_Motor a, pga3_Motor b) {
    const double t0 = a.scalar * b.scalar;
    const double t1 = a.scalar * b.e01;
    const double t2 = a.scalar * b.e02;
    const double t3 = a.scalar * b.e12;
    const double t4 = a.scalar * b.e03;
    const double t5 = a.scalar * b.e13;
    const double t6 = a.scalar * b.e23;
    const double t7 = a.scalar * b.e0123;
    const double t8 = a.e01 * b.scalar;
    const double t9 = a.e01 * b.e12;
    const double t10 = a.e01 * b.e13;
    const double t11 = a.e01 * b.e23;
    const double t12 = a.e02 * b.scalar;
    const double t13 = a.e02 * b.e12;
    const double t14 = a.e02 * b.e13;
    const double t15 = a.e02 * b.e23;
    const double t16 = a.e12 * b.scalar;
    const double t17 = a.e12 * b.e01;
    const double t18 = a.e12 * b.e02;
    const double t19 = a.e12 * b.e12;
    const double t20 = a.e12 * b.e03;
    const double t21 = a.e12 * b.e13;
    const double t22 = a.e12 * b.e23;
    const double t23 = a.e12 * b.e0123;
    const double t24 = a.e03 * b.scalar;
    const double t25 = a.e03 * b.e12;
    const double t26 = a.e03 * b.e13;
    const double t27 = a.e03 * b.e23;
    const double t28 = a.e13 * b.scalar;
    const double t29 = a.e13 * b.e01;
    const double t30 = a.e13 * b.e02;
    const double t31 = a.e13 * b.e12;
    const double t32 = a.e13 * b.e03;
    const double t33 = a.e13 * b.e13;
    const double t34 = a.e13 * b.e23;
    const double t35 = a.e13 * b.e0123;
    const double t36 = a.e23 * b.scalar;
    const double t37 = a.e23 * b.e01;
    const double t38 = a.e23 * b.e02;
    const double t39 = a.e23 * b.e12;
    const double t40 = a.e23 * b.e03;
    const double t41 = a.e23 * b.e13;
    const double t42 = a.e23 * b.e23;
    const double t43 = a.e23 * b.e0123;
    const double t44 = a.e0123 * b.scalar;
    const double t45 = a.e0123 * b.e12;
    const double t46 = a.e0123 * b.e13;
    const double t47 = a.e0123 * b.e23;
    pga3_Motor r;
    r.scalar = ((t0 - t19) - t33) - t42;
    r.e01 = (((t1 + t8) - t13) + t18) - (((t26 - t32) + t43) + t47);
    r.e02 = (((t2 + t9) + t12) - t17) - (((t27 - t35) - t40) - t46);
    r.e12 = ((t3 + t16) - t34) + t41;
    r.e03 = (((t4 + t10) + t15) - t23) + (((t24 - t29) - t38) - t45);
    r.e13 = ((t5 + t22) + t28) - t39;
    r.e23 = ((t6 - t21) + t31) + t36;
    r.e0123 = (((t7 + t11) - t14) + t20) + (((t25 - t30) + t37) + t44);
    return r;
}

/* `gp` of a Motor and a Point. */
static inline pga3_Odd pga3_motor_gp_point(pga3_Motor a, pga3_Point b) {
    const double t0 = a.scalar * b.e012;
    const double t1 = a.scalar * b.e013;
    const double t2 = a.scalar * b.e023;
    const double t3 = a.scalar * b.e123;
    const double t4 = a.e01 * b.e123;
    const double t5 = a.e02 * b.e123;
    const double t6 = a.e12 * b.e012;
    const double t7 = a.e12 * b.e013;
    const double t8 = a.e12 * b.e023;
    const double t9 = a.e12 * b.e123;
    const double t10 = a.e03 * b.e123;
    const double t11 = a.e13 * b.e012;
    const double t12 = a.e13 * b.e013;
    const double t13 = a.e13 * b.e023;
    const double t14 = a.e13 * b.e123;
    const double t15 = a.e23 * b.e012;
    const double t16 = a.e23 * b.e013;
    const double t17 = a.e23 * b.e023;
    const double t18 = a.e23 * b.e123;
    const double t19 = a.e0123 * b.e123;
    pga3_Odd r;
    r.e0 = (((-t6) - t12) - t17) - t19;
    r.e1 = -t18;
    r.e2 = t14;
    r.e3 = -t9;
    r.e012 = ((t0 + t10) - t13) + t16;
    r.e013 = ((t1 - t5) + t8) - t15;
    r.e023 = ((t2 + t4) - t7) + t11;
    r.e123 = t3;
    return r;
}

/* `gp` of a Motor and a Line. */
static inline pga3_Motor pga3_motor_gp_line(pga3_Motor a, pga3_Line b) {
    const double t0 = a.scalar * b.e01;
    const double t1 = a.scalar * b.e02;
    const double t2 = a.scalar * b.e12;
    const double t3 = a.scalar * b.e03;
    const double t4 = a.scalar * b.e13;
    const double t5 = a.scalar * b.e23;
    const double t6 = a.e01 * b.e12;
    const double t7 = a.e01 * b.e13;
    const double t8 = a.e01 * b.e23;
    const double t9 = a.e02 * b.e12;
    const double t10 = a.e02 * b.e13;
    const double t11 = a.e02 * b.e23;
    const double t12 = a.e12 * b.e01;
    const double t13 = a.e12 * b.e02;
    const double t14 = a.e12 * b.e12;
    const double t15 = a.e12 * b.e03;
    const double t16 = a.e12 * b.e13;
    const double t17 = a.e12 * b.e23;
    const double t18 = a.e03 * b.e12;
    const double t19 = a.e03 * b.e13;
    const double t20 = a.e03 * b.e23;
    const double t21 = a.e13 * b.e01;
    const double t22 = a.e13 * b.e02;
    const double t23 = a.e13 * b.e12;
    const double t24 = a.e13 * b.e03;
    const double t25 = a.e13 * b.e13;
    const double t26 = a.e13 * b.e23;
    const double t27 = a.e23 * b.e01;
    const double t28 = a.e23 * b.e02;
    const double t29 = a.e23 * b.e12;
    const double t30 = a.e23 * b.e03;
    const double t31 = a.e23 * b.e13;
    const double t32 = a.e23 * b.e23;
    const double t33 = a.e0123 * b.e12;
    const double t34 = a.e0123 * b.e13;
    const double t35 = a.e0123 * b.e23;
    pga3_Motor r;
    r.scalar = ((-t14) - t25) - t32;
    r.e01 = (((t0 - t9) + t13) - t19) + (t24 - t35);
    r.e02 = (((t1 + t6) - t12) - t20) + (t30 + t34);
    r.e12 = (t2 - t26) + t31;
    r.e03 = (((t3 + t7) + t11) - t21) - (t28 + t33);
    r.e13 = (t4 + t17) - t29;
    r.e23 = (t5 - t16) + t23;
    r.e0123 = (((t8 - t10) + t15) + t18) - (t22 - t27);
    return r;
}

/* `gp` of a Point and a Motor. */
static inline pga3_Odd pga3_point_gp_motor(pga3_Point a, pga3_Motor b) {
    const double t0 = a.e012 * b.scalar;
    const double t1 = a.e012 * b.e12;
    const double t2 = a.e012 * b.e13;
    const double t3 = a.e012 * b.e23;
    const double t4 = a.e013 * b.scalar;
    const double t5 = a.e013 * b.e12;
    const double t6 = a.e013 * b.e13;
    const double t7 = a.e013 * b.e23;
    const double t8 = a.e023 * b.scalar;
    const double t9 = a.e023 * b.e12;
    const double t10 = a.e023 * b.e13;
    const double t11 = a.e023 * b.e23;
    const double t12 = a.e123 * b.scalar;
    const double t13 = a.e123 * b.e01;
    const double t14 = a.e123 * b.e02;
    const double t15 = a.e123 * b.e12;
    const double t16 = a.e123 * b.e03;
    const double t17 = a.e123 * b.e13;
    const double t18 = a.e123 * b.e23;
    const double t19 = a.e123 * b.e0123;
    pga3_Odd r;
    r.e0 = ((t19 - t6) - t11) - t1;
    r.e1 = -t18;
    r.e2 = t17;
    r.e3 = -t15;
    r.e012 = ((t0 - t7) + t10) - t16;
    r.e013 = ((t3 + t4) - t9) + t14;
    r.e023 = ((t5 - t2) + t8) - t13;
    r.e123 = t12;
    return r;
}

/* `gp` of a Point and a Point. */
static inline pga3_Motor pga3_point_gp_point(pga3_Point a, pga3_Point b) {
    const double t0 = a.e012 * b.e123;
    const double t1 = a.e013 * b.e123;
    const double t2 = a.e023 * b.e123;
    const double t3 = a.e123 * b.e012;
    const double t4 = a.e123 * b.e013;
    const double t5 = a.e123 * b.e023;
    const double t6 = a.e123 * b.e123;
    pga3_Motor r;
    r.scalar = -t6;
    r.e01 = t5 - t2;
    r.e02 = t1 - t4;
    r.e12 = 0.0;
    r.e03 = t3 - t0;
    r.e13 = 0.0;
    r.e23 = 0.0;
    r.e0123 = 0.0;
    return r;
}

/* `gp` of a Point and a Line. */
static inline pga3_Odd pga3_point_gp_line(pga3_Point a, pga3_Line b) {
    const double t0 = a.e012 * b.e12;
    const double t1 = a.e012 * b.e13;
    const double t2 = a.e012 * b.e23;
    const double t3 = a.e013 * b.e12;
    const double t4 = a.e013 * b.e13;
    const double t5 = a.e013 * b.e23;
    const double t6 = a.e023 * b.e12;
    const double t7 = a.e023 * b.e13;
    const double t8 = a.e023 * b.e23;
    const double t9 = a.e123 * b.e01;
    const double t10 = a.e123 * b.e02;
    const double t11 = a.e123 * b.e12;
    const double t12 = a.e123 * b.e03;
    const double t13 = a.e123 * b.e13;
    const double t14 = a.e123 * b.e23;
    pga3_Odd r;
    r.e0 = ((-t0) - t4) - t8;
    r.e1 = -t14;
    r.e2 = t13;
    r.e3 = -t11;
    r.e012 = (t7 - t5) - t12;
    r.e013 = (t2 - t6) + t10;
    r.e023 = (t3 - t1) - t9;
    r.e123 = 0.0;
    return r;
}

/* `gp` of a Line and a Motor. */
static inline pga3_Motor pga3_line_gp_motor(pga3_Line a, pga3_Motor b) {
    const double t0 = a.e01 * b.scalar;
    const double t1 = a.e01 * b.e12;
    const double t2 = a.e01 * b.e13;
    const double t3 = a.e01 * b.e23;
    const double t4 = a.e02 * b.scalar;
    const double t5 = a.e02 * b.e12;
    const double t6 = a.e02 * b.e13;
    const double t7 = a.e02 * b.e23;
    const double t8 = a.e12 * b.scalar;
    const double t9 = a.e12 * b.e01;
    const double t10 = a.e12 * b.e02;
    const double t11 = a.e12 * b.e12;
    const double t12 = a.e12 * b.e03;
    const double t13 = a.e12 * b.e13;
    const double t14 = a.e12 * b.e23;
    const double t15 = a.e12 * b.e0123;
    const double t16 = a.e03 * b.scalar;
    const double t17 = a.e03 * b.e12;
    const double t18 = a.e03 * b.e13;
    const double t19 = a.e03 * b.e23;
    const double t20 = a.e13 * b.scalar;
    const double t21 = a.e13 * b.e01;
    const double t22 = a.e13 * b.e02;
    const double t23 = a.e13 * b.e12;
    const double t24 = a.e13 * b.e03;
    const double t25 = a.e13 * b.e13;
    const double t26 = a.e13 * b.e23;
    const double t27 = a.e13 * b.e0123;
    const double t28 = a.e23 * b.scalar;
    const double t29 = a.e23 * b.e01;
    const double t30 = a.e23 * b.e02;
    const double t31 = a.e23 * b.e12;
    const double t32 = a.e23 * b.e03;
    const double t33 = a.e23 * b.e13;
    const double t34 = a.e23 * b.e23;
    const double t35 = a.e23 * b.e0123;
    pga3_Motor r;
    r.scalar = ((-t11) - t25) - t34;
    r.e01 = (((t0 - t5) + t10) - t18) + (t24 - t35);
    r.e02 = (((t1 + t4) - t9) - t19) + (t27 + t32);
    r.e12 = (t8 - t26) + t33;
    r.e03 = (((t2 + t7) - t15) + t16) - (t21 + t30);
    r.e13 = (t14 + t20) - t31;
    r.e23 = (t23 - t13) + t28;
    r.e0123 = (((t3 - t6) + t12) + t17) - (t22 - t29);
    return r;
}

/* `gp` of a Line and a Point. */
static inline pga3_Odd pga3_line_gp_point(pga3_Line a, pga3_Point b) {
    const double t0 = a.e01 * b.e123;
    const double t1 = a.e02 * b.e123;
    const double t2 = a.e12 * b.e012;
    const double t3 = a.e12 * b.e013;
    const double t4 = a.e12 * b.e023;
    const double t5 = a.e12 * b.e123;
    const double t6 = a.e03 * b.e123;
    const double t7 = a.e13 * b.e012;
    const double t8 = a.e13 * b.e013;
    const double t9 = a.e13 * b.e023;
    const double t10 = a.e13 * b.e123;
    const double t11 = a.e23 * b.e012;
    const double t12 = a.e23 * b.e013;
    const double t13 = a.e23 * b.e023;
    const double t14 = a.e23 * b.e123;
    pga3_Odd r;
    r.e0 = ((-t2) - t8) - t13;
    r.e1 = -t14;
    r.e2 = t10;
    r.e3 = -t5;
    r.e012 = (t6 - t9) + t12;
    r.e013 = (t4 - t1) - t11;
    r.e023 = (t0 - t3) + t7;
    r.e123 = 0.0;
    return r;
}

/* `gp` of a Line and a Line. */
static inline pga3_Motor pga3_line_gp_line(pga3_Line a, pga3_Line b) {
    const double t0 = a.e01 * b.e12;
    const double t1 = a.e01 * b.e13;
    const double t2 = a.e01 * b.e23;
    const double t3 = a.e02 * b.e12;
    const double t4 = a.e02 * b.e13;
    const double t5 = a.e02 * b.e23;
    const double t6 = a.e12 * b.e01;
    const double t7 = a.e12 * b.e02;
    const double t8 = a.e12 * b.e12;
    const double t9 = a.e12 * b.e03;
    const double t10 = a.e12 * b.e13;
    const double t11 = a.e12 * b.e23;
    const double t12 = a.e03 * b.e12;
    const double t13 = a.e03 * b.e13;
    const double t14 = a.e03 * b.e23;
    const double t15 = a.e13 * b.e01;
    const double t16 = a.e13 * b.e02;
    const double t17 = a.e13 * b.e12;
    const double t18 = a.e13 * b.e03;
    const double t19 = a.e13 * b.e13;
    const double t20 = a.e13 * b.e23;
    const double t21 = a.e23 * b.e01;
    const double t22 = a.e23 * b.e02;
    const double t23 = a.e23 * b.e12;
    const double t24 = a.e23 * b.e03;
    const double t25 = a.e23 * b.e13;
    const double t26 = a.e23 * b.e23;
    pga3_Motor r;
    r.scalar = ((-t8) - t19) - t26;
    r.e01 = ((t7 - t3) - t13) + t18;
    r.e02 = ((t0 - t6) - t14) + t24;
    r.e12 = t25 - t20;
    r.e03 = ((t1 + t5) - t15) - t22;
    r.e13 = t11 - t23;
    r.e23 = t17 - t10;
    r.e0123 = (((t2 - t4) + t9) + t12) - (t16 - t21);
    return r;
}

/* The reverse of a Motor. */
static inline pga3_Motor pga3_motor_reverse(pga3_Motor x) {
    pga3_Motor r;
    r.scalar = x.scalar;
    r.e01 = -x.e01;
    r.e02 = -x.e02;
    r.e12 = -x.e12;
    r.e03 = -x.e03;
    r.e13 = -x.e13;
    r.e23 = -x.e23;
    r.e0123 = x.e0123;
    return r;
}

/* The squared norm <x rev(x)>_0 of a Motor (may be negative or zero). */
static inline double pga3_motor_norm_squared(pga3_Motor x) {
    const double t0 = x.scalar * x.scalar;
    const double t1 = x.e12 * x.e12;
    const double t2 = x.e13 * x.e13;
    const double t3 = x.e23 * x.e23;
    return ((t0 + t1) + t2) + t3;
}

/* The reverse of a Point. */
static inline pga3_Point pga3_point_reverse(pga3_Point x) {
    pga3_Point r;
    r.e012 = -x.e012;
    r.e013 = -x.e013;
    r.e023 = -x.e023;
    r.e123 = -x.e123;
    return r;
}

/* The squared norm <x rev(x)>_0 of a Point (may be negative or zero). */
static inline double pga3_point_norm_squared(pga3_Point x) {
    const double t0 = x.e123 * x.e123;
    return t0;
}

/* The reverse of a Line. */
static inline pga3_Line pga3_line_reverse(pga3_Line x) {
    pga3_Line r;
    r.e01 = -x.e01;
    r.e02 = -x.e02;
    r.e12 = -x.e12;
    r.e03 = -x.e03;
    r.e13 = -x.e13;
    r.e23 = -x.e23;
    return r;
}

/* The squared norm <x rev(x)>_0 of a Line (may be negative or zero). */
static inline double pga3_line_norm_squared(pga3_Line x) {
    const double t0 = x.e12 * x.e12;
    const double t1 = x.e13 * x.e13;
    const double t2 = x.e23 * x.e23;
    return (t0 + t1) + t2;
}

/* S x rev(S) for a Motor S and a Motor x, in one fused kernel. */
static inline pga3_Motor pga3_motor_apply_motor(pga3_Motor s, pga3_Motor x) {
    const double t0 = ((s.scalar * x.scalar) - (s.e12 * x.e12)) - ((s.e13 * x.e13) + (s.e23 * x.e23));
    const double t1 = (((s.scalar * x.e01) + (s.e01 * x.scalar)) - ((s.e02 * x.e12) - (s.e12 * x.e02))) - (((s.e03 * x.e13) - (s.e13 * x.e03)) + ((s.e23 * x.e0123) + (s.e0123 * x.e23)));
    const double t2 = (((s.scalar * x.e02) + (s.e01 * x.e12)) + ((s.e02 * x.scalar) - (s.e12 * x.e01))) - (((s.e03 * x.e23) - (s.e13 * x.e0123)) - ((s.e23 * x.e03) + (s.e0123 * x.e13)));
    const double t3 = ((s.scalar * x.e12) + (s.e12 * x.scalar)) - ((s.e13 * x.e23) - (s.e23 * x.e13));
    const double t4 = (((s.scalar * x.e03) + (s.e01 * x.e13)) + ((s.e02 * x.e23) - (s.e12 * x.e0123))) + (((s.e03 * x.scalar) - (s.e13 * x.e01)) - ((s.e23 * x.e02) + (s.e0123 * x.e12)));
    const double t5 = ((s.scalar * x.e13) + (s.e12 * x.e23)) + ((s.e13 * x.scalar) - (s.e23 * x.e12));
    const double t6 = ((s.scalar * x.e23) - (s.e12 * x.e13)) + ((s.e13 * x.e12) + (s.e23 * x.scalar));
    const double t7 = (((s.scalar * x.e0123) + (s.e01 * x.e23)) - ((s.e02 * x.e13) - (s.e12 * x.e03))) + (((s.e03 * x.e12) - (s.e13 * x.e02)) + ((s.e23 * x.e01) + (s.e0123 * x.scalar)));
    pga3_Motor r;
    r.scalar = ((t0 * s.scalar) + (t3 * s.e12)) + ((t5 * s.e13) + (t6 * s.e23));
    r.e01 = (((t1 * s.scalar) - (t0 * s.e01)) - ((t3 * s.e02) - (t2 * s.e12))) - (((t5 * s.e03) - (t4 * s.e13)) - ((t7 * s.e23) - (t6 * s.e0123)));
    r.e02 = (((t2 * s.scalar) + (t3 * s.e01)) - ((t0 * s.e02) + (t1 * s.e12))) - (((t6 * s.e03) + (t7 * s.e13)) - ((t4 * s.e23) + (t5 * s.e0123)));
    r.e12 = ((t3 * s.scalar) - (t0 * s.e12)) - ((t6 * s.e13) - (t5 * s.e23));
    r.e03 = (((t4 * s.scalar) + (t5 * s.e01)) + ((t6 * s.e02) + (t7 * s.e12))) - (((t0 * s.e03) + (t1 * s.e13)) + ((t2 * s.e23) + (t3 * s.e0123)));
    r.e13 = ((t5 * s.scalar) + (t6 * s.e12)) - ((t0 * s.e13) + (t3 * s.e23));
    r.e23 = ((t6 * s.scalar) - (t5 * s.e12)) + ((t3 * s.e13) - (t0 * s.e23));
    r.e0123 = (((t7 * s.scalar) - (t6 * s.e01)) + ((t5 * s.e02) - (t4 * s.e12))) - (((t3 * s.e03) - (t2 * s.e13)) + ((t1 * s.e23) - (t0 * s.e0123)));
    return r;
}

/* S x rev(S) for a Motor S and a Point x, in one fused kernel. */
static inline pga3_Point pga3_motor_apply_point(pga3_Motor s, pga3_Point x) {
    const double t0 = (-s.e0123) * x.e123;
    const double t1 = (s.e03 * x.e123) - ((s.e13 * x.e023) + ((-s.e23) * x.e013));
    const double t2 = -((s.e02 * x.e123) - ((s.e12 * x.e023) + ((-s.e23) * x.e012)));
    const double t3 = (s.e01 * x.e123) - ((s.e12 * x.e013) - (s.e13 * x.e012));
    const double t4 = ((s.scalar * s.scalar) + (s.e23 * s.e23)) + ((s.e12 * s.e12) + (s.e13 * s.e13));
    const double t5 = (((t1 * s.scalar) - (t0 * s.e12)) - (t3 * s.e13)) - (t2 * (-s.e23));
    const double t6 = (((t2 * s.scalar) + (t3 * s.e12)) + (t1 * (-s.e23))) - (t0 * s.e13);
    const double t7 = (((t3 * s.scalar) + (t1 * s.e13)) + (t0 * (-s.e23))) - (t2 * s.e12);
    pga3_Point r;
    r.e012 = (t4 * x.e012) + (t5 + t5);
    r.e013 = (t4 * x.e013) + (t6 + t6);
    r.e023 = (t4 * x.e023) + (t7 + t7);
    r.e123 = t4 * x.e123;
    return r;
}

/* S x rev(S) for a Motor S and a Line x, in one fused kernel. */
static inline pga3_Line pga3_motor_apply_line(pga3_Motor s, pga3_Line x) {
    const double t0 = -((s.e12 * x.e12) + ((s.e13 * x.e13) + (s.e23 * x.e23)));
    const double t1 = ((s.scalar * x.e01) - ((s.e02 * x.e12) - (s.e12 * x.e02))) - ((s.e03 * x.e13) - ((s.e13 * x.e03) - (s.e0123 * x.e23)));
    const double t2 = ((s.scalar * x.e02) + ((s.e01 * x.e12) - (s.e12 * x.e01))) - ((s.e03 * x.e23) - ((s.e23 * x.e03) + (s.e0123 * x.e13)));
    const double t3 = (s.scalar * x.e12) - ((s.e13 * x.e23) - (s.e23 * x.e13));
    const double t4 = ((s.scalar * x.e03) + ((s.e01 * x.e13) + (s.e02 * x.e23))) - ((s.e13 * x.e01) + ((s.e23 * x.e02) + (s.e0123 * x.e12)));
    const double t5 = (s.scalar * x.e13) + ((s.e12 * x.e23) - (s.e23 * x.e12));
    const double t6 = (s.scalar * x.e23) - ((s.e12 * x.e13) - (s.e13 * x.e12));
    const double t7 = ((s.e01 * x.e23) - ((s.e02 * x.e13) - (s.e12 * x.e03))) + ((s.e03 * x.e12) - ((s.e13 * x.e02) - (s.e23 * x.e01)));
    pga3_Line r;
    r.e01 = (((t1 * s.scalar) - (t0 * s.e01)) - ((t3 * s.e02) - (t2 * s.e12))) - (((t5 * s.e03) - (t4 * s.e13)) - ((t7 * s.e23) - (t6 * s.e0123)));
    r.e02 = (((t2 * s.scalar) + (t3 * s.e01)) - ((t0 * s.e02) + (t1 * s.e12))) - (((t6 * s.e03) + (t7 * s.e13)) - ((t4 * s.e23) + (t5 * s.e0123)));
    r.e12 = ((t3 * s.scalar) - (t0 * s.e12)) - ((t6 * s.e13) - (t5 * s.e23));
    r.e03 = (((t4 * s.scalar) + (t5 * s.e01)) + ((t6 * s.e02) + (t7 * s.e12))) - (((t0 * s.e03) + (t1 * s.e13)) + ((t2 * s.e23) + (t3 * s.e0123)));
    r.e13 = ((t5 * s.scalar) + (t6 * s.e12)) - ((t0 * s.e13) + (t3 * s.e23));
    r.e23 = ((t6 * s.scalar) - (t5 * s.e12)) + ((t3 * s.e13) - (t0 * s.e23));
    return r;
}

/* S x rev(S) for a Point S and a Motor x, in one fused kernel. */
static inline pga3_Motor pga3_point_apply_motor(pga3_Point s, pga3_Motor x) {
    const double t0 = s.e123 * x.e0123;
    const double t1 = -((s.e013 * x.e23) - ((s.e023 * x.e13) - (s.e123 * x.e03)));
    const double t2 = (s.e012 * x.e23) - ((s.e023 * x.e12) - (s.e123 * x.e02));
    const double t3 = -((s.e012 * x.e13) - ((s.e013 * x.e12) - (s.e123 * x.e01)));
    const double t4 = s.e123 * s.e123;
    const double t5 = t3 * s.e123;
    const double t6 = -(t2 * s.e123);
    const double t7 = t1 * s.e123;
    const double t8 = -(t0 * s.e123);
    pga3_Motor r;
    r.scalar = t4 * x.scalar;
    r.e01 = (t4 * x.e01) + (t5 + t5);
    r.e02 = (t4 * x.e02) + (t6 + t6);
    r.e12 = t4 * x.e12;
    r.e03 = (t4 * x.e03) + (t7 + t7);
    r.e13 = t4 * x.e13;
    r.e23 = t4 * x.e23;
    r.e0123 = (t4 * x.e0123) + (t8 + t8);
    return r;
}

/* S x rev(S) for a Point S and a Point x, in one fused kernel. */
static inline pga3_Point pga3_point_apply_point(pga3_Point s, pga3_Point x) {
    const double t0 = -(s.e123 * x.e123);
    const double t1 = -((s.e023 * x.e123) - (s.e123 * x.e023));
    const double t2 = (s.e013 * x.e123) - (s.e123 * x.e013);
    const double t3 = -((s.e012 * x.e123) - (s.e123 * x.e012));
    pga3_Point r;
    r.e012 = -((t0 * s.e012) + (t3 * s.e123));
    r.e013 = (t2 * s.e123) - (t0 * s.e013);
    r.e023 = -((t0 * s.e023) + (t1 * s.e123));
    r.e123 = -(t0 * s.e123);
    return r;
}

/* S x rev(S) for a Point S and a Line x, in one fused kernel. */
static inline pga3_Line pga3_point_apply_line(pga3_Point s, pga3_Line x) {
    const double t0 = -(s.e123 * x.e23);
    const double t1 = s.e123 * x.e13;
    const double t2 = -((s.e013 * x.e23) - ((s.e023 * x.e13) - (s.e123 * x.e03)));
    const double t3 = -(s.e123 * x.e12);
    const double t4 = (s.e012 * x.e23) - ((s.e023 * x.e12) - (s.e123 * x.e02));
    const double t5 = -((s.e012 * x.e13) - ((s.e013 * x.e12) - (s.e123 * x.e01)));
    pga3_Line r;
    r.e01 = (t5 * s.e123) - ((t1 * s.e012) + (t3 * s.e013));
    r.e02 = (t0 * s.e012) - ((t3 * s.e023) + (t4 * s.e123));
    r.e12 = -(t3 * s.e123);
    r.e03 = (t0 * s.e013) + ((t1 * s.e023) + (t2 * s.e123));
    r.e13 = t1 * s.e123;
    r.e23 = -(t0 * s.e123);
    return r;
}

/* S x rev(S) for a Line S and a Motor x, in one fused kernel. */
static inline pga3_Motor pga3_line_apply_motor(pga3_Line s, pga3_Motor x) {
    const double t0 = -((s.e12 * x.e12) + ((s.e13 * x.e13) + (s.e23 * x.e23)));
    const double t1 = ((s.e01 * x.scalar) - ((s.e02 * x.e12) - (s.e12 * x.e02))) - ((s.e03 * x.e13) - ((s.e13 * x.e03) - (s.e23 * x.e0123)));
    const double t2 = ((s.e01 * x.e12) + ((s.e02 * x.scalar) - (s.e12 * x.e01))) - ((s.e03 * x.e23) - ((s.e13 * x.e0123) + (s.e23 * x.e03)));
    const double t3 = (s.e12 * x.scalar) - ((s.e13 * x.e23) - (s.e23 * x.e13));
    const double t4 = ((s.e01 * x.e13) + ((s.e02 * x.e23) - (s.e12 * x.e0123))) + ((s.e03 * x.scalar) - ((s.e13 * x.e01) + (s.e23 * x.e02)));
    const double t5 = (s.e12 * x.e23) + ((s.e13 * x.scalar) - (s.e23 * x.e12));
    const double t6 = -((s.e12 * x.e13) - ((s.e13 * x.e12) + (s.e23 * x.scalar)));
    const double t7 = ((s.e01 * x.e23) - ((s.e02 * x.e13) - (s.e12 * x.e03))) + ((s.e03 * x.e12) - ((s.e13 * x.e02) - (s.e23 * x.e01)));
    pga3_Motor r;
    r.scalar = (t3 * s.e12) + ((t5 * s.e13) + (t6 * s.e23));
    r.e01 = ((t2 * s.e12) - ((t0 * s.e01) + (t3 * s.e02))) - ((t5 * s.e03) - ((t4 * s.e13) + (t7 * s.e23)));
    r.e02 = ((t3 * s.e01) - ((t0 * s.e02) + (t1 * s.e12))) - ((t6 * s.e03) + ((t7 * s.e13) - (t4 * s.e23)));
    r.e12 = (t5 * s.e23) - ((t0 * s.e12) + (t6 * s.e13));
    r.e03 = ((t5 * s.e01) + ((t6 * s.e02) + (t7 * s.e12))) - ((t0 * s.e03) + ((t1 * s.e13) + (t2 * s.e23)));
    r.e13 = (t6 * s.e12) - ((t0 * s.e13) + (t3 * s.e23));
    r.e23 = (t3 * s.e13) - ((t5 * s.e12) + (t0 * s.e23));
    r.e0123 = ((t5 * s.e02) - ((t6 * s.e01) + (t4 * s.e12))) - ((t3 * s.e03) - ((t2 * s.e13) - (t1 * s.e23)));
    return r;
}

/* S x rev(S) for a Line S and a Point x, in one fused kernel. */
static inline pga3_Point pga3_line_apply_point(pga3_Line s, pga3_Point x) {
    const double t0 = (s.e03 * x.e123) - ((s.e13 * x.e023) - (s.e23 * x.e013));
    const double t1 = -((s.e02 * x.e123) - ((s.e12 * x.e023) - (s.e23 * x.e012)));
    const double t2 = (s.e01 * x.e123) - ((s.e12 * x.e013) - (s.e13 * x.e012));
    const double t3 = (s.e12 * s.e12) + ((s.e13 * s.e13) + (s.e23 * s.e23));
    const double t4 = (t1 * s.e23) - (t2 * s.e13);
    const double t5 = (t2 * s.e12) - (t0 * s.e23);
    const double t6 = (t0 * s.e13) - (t1 * s.e12);
    pga3_Point r;
    r.e012 = (t3 * x.e012) + (t4 + t4);
    r.e013 = (t3 * x.e013) + (t5 + t5);
    r.e023 = (t3 * x.e023) + (t6 + t6);
    r.e123 = t3 * x.e123;
    return r;
}

/* S x rev(S) for a Line S and a Line x, in one fused kernel. */
static inline pga3_Line pga3_line_apply_line(pga3_Line s, pga3_Line x) {
    const double t0 = -((s.e12 * x.e12) + ((s.e13 * x.e13) + (s.e23 * x.e23)));
    const double t1 = -(((s.e02 * x.e12) - (s.e12 * x.e02)) + ((s.e03 * x.e13) - (s.e13 * x.e03)));
    const double t2 = ((s.e01 * x.e12) - (s.e12 * x.e01)) - ((s.e03 * x.e23) - (s.e23 * x.e03));
    const double t3 = -((s.e13 * x.e23) - (s.e23 * x.e13));
    const double t4 = ((s.e01 * x.e13) + (s.e02 * x.e23)) - ((s.e13 * x.e01) + (s.e23 * x.e02));
    const double t5 = (s.e12 * x.e23) - (s.e23 * x.e12);
    const double t6 = -((s.e12 * x.e13) - (s.e13 * x.e12));
    const double t7 = ((s.e01 * x.e23) - ((s.e02 * x.e13) - (s.e12 * x.e03))) + ((s.e03 * x.e12) - ((s.e13 * x.e02) - (s.e23 * x.e01)));
    pga3_Line r;
    r.e01 = ((t2 * s.e12) - ((t0 * s.e01) + (t3 * s.e02))) - ((t5 * s.e03) - ((t4 * s.e13) + (t7 * s.e23)));
    r.e02 = ((t3 * s.e01) - ((t0 * s.e02) + (t1 * s.e12))) - ((t6 * s.e03) + ((t7 * s.e13) - (t4 * s.e23)));
    r.e12 = (t5 * s.e23) - ((t0 * s.e12) + (t6 * s.e13));
    r.e03 = ((t5 * s.e01) + ((t6 * s.e02) + (t7 * s.e12))) - ((t0 * s.e03) + ((t1 * s.e13) + (t2 * s.e23)));
    r.e13 = (t6 * s.e12) - ((t0 * s.e13) + (t3 * s.e23));
    r.e23 = (t3 * s.e13) - ((t5 * s.e12) + (t0 * s.e23));
    return r;
}

/* S x rev(S) for a unit Motor S (S rev(S) = 1) and a Motor x; not the action otherwise. */
static inline pga3_Motor pga3_motor_apply_unit_motor(pga3_Motor s, pga3_Motor x) {
    const double t0 = -(((s.e02 * x.e12) - (s.e12 * x.e02)) + ((s.e03 * x.e13) - (s.e13 * x.e03)));
    const double t1 = ((s.e01 * x.e12) - (s.e12 * x.e01)) - ((s.e03 * x.e23) - (s.e23 * x.e03));
    const double t2 = -((s.e13 * x.e23) - (s.e23 * x.e13));
    const double t3 = ((s.e01 * x.e13) + (s.e02 * x.e23)) - ((s.e13 * x.e01) + (s.e23 * x.e02));
    const double t4 = (s.e12 * x.e23) - (s.e23 * x.e12);
    const double t5 = -((s.e12 * x.e13) - (s.e13 * x.e12));
    const double t6 = ((t0 * s.scalar) + ((t1 * s.e12) - (t2 * s.e02))) + ((t3 * s.e13) - ((t4 * s.e03) + (t5 * s.e0123)));
    const double t7 = -(((t0 * s.e12) - ((t1 * s.scalar) + (t2 * s.e01))) - ((t3 * s.e23) + ((t4 * s.e0123) - (t5 * s.e03))));
    const double t8 = (t2 * s.scalar) + ((t4 * s.e23) - (t5 * s.e13));
    const double t9 = -(((t0 * s.e13) + ((t1 * s.e23) + (t2 * s.e0123))) - ((t3 * s.scalar) + ((t4 * s.e01) + (t5 * s.e02))));
    const double t10 = -((t2 * s.e23) - ((t4 * s.scalar) + (t5 * s.e12)));
    const double t11 = (t2 * s.e13) - ((t4 * s.e12) - (t5 * s.scalar));
    pga3_Motor r;
    r.scalar = x.scalar;
    r.e01 = (x.e01 + t6) + t6;
    r.e02 = (x.e02 + t7) + t7;
    r.e12 = (x.e12 + t8) + t8;
    r.e03 = (x.e03 + t9) + t9;
    r.e13 = (x.e13 + t10) + t10;
    r.e23 = (x.e23 + t11) + t11;
    r.e0123 = x.e0123;
    return r;
}

/* S x rev(S) for a unit Motor S (S rev(S) = 1) and a Point x; not the action otherwise. */
static inline pga3_Point pga3_motor_apply_unit_point(pga3_Motor s, pga3_Point x) {
    const double t0 = -(s.e0123 * x.e123);
    const double t1 = (s.e03 * x.e123) - ((s.e13 * x.e023) - (s.e23 * x.e013));
    const double t2 = -((s.e02 * x.e123) - ((s.e12 * x.e023) - (s.e23 * x.e012)));
    const double t3 = (s.e01 * x.e123) - ((s.e12 * x.e013) - (s.e13 * x.e012));
    const double t4 = -(((t0 * s.e12) - (t1 * s.scalar)) - ((t2 * s.e23) - (t3 * s.e13)));
    const double t5 = -(((t0 * s.e13) + (t1 * s.e23)) - ((t2 * s.scalar) + (t3 * s.e12)));
    const double t6 = -(((t0 * s.e23) - (t1 * s.e13)) + ((t2 * s.e12) - (t3 * s.scalar)));
    pga3_Point r;
    r.e012 = (x.e012 + t4) + t4;
    r.e013 = (x.e013 + t5) + t5;
    r.e023 = (x.e023 + t6) + t6;
    r.e123 = x.e123;
    return r;
}

/* S x rev(S) for a unit Motor S (S rev(S) = 1) and a Line x; not the action otherwise. */
static inline pga3_Line pga3_motor_apply_unit_line(pga3_Motor s, pga3_Line x) {
    const double t0 = -(((s.e02 * x.e12) - (s.e12 * x.e02)) + ((s.e03 * x.e13) - (s.e13 * x.e03)));
    const double t1 = ((s.e01 * x.e12) - (s.e12 * x.e01)) - ((s.e03 * x.e23) - (s.e23 * x.e03));
    const double t2 = -((s.e13 * x.e23) - (s.e23 * x.e13));
    const double t3 = ((s.e01 * x.e13) + (s.e02 * x.e23)) - ((s.e13 * x.e01) + (s.e23 * x.e02));
    const double t4 = (s.e12 * x.e23) - (s.e23 * x.e12);
    const double t5 = -((s.e12 * x.e13) - (s.e13 * x.e12));
    const double t6 = ((t0 * s.scalar) + ((t1 * s.e12) - (t2 * s.e02))) + ((t3 * s.e13) - ((t4 * s.e03) + (t5 * s.e0123)));
    const double t7 = -(((t0 * s.e12) - ((t1 * s.scalar) + (t2 * s.e01))) - ((t3 * s.e23) + ((t4 * s.e0123) - (t5 * s.e03))));
    const double t8 = (t2 * s.scalar) + ((t4 * s.e23) - (t5 * s.e13));
    const double t9 = -(((t0 * s.e13) + ((t1 * s.e23) + (t2 * s.e0123))) - ((t3 * s.scalar) + ((t4 * s.e01) + (t5 * s.e02))));
    const double t10 = -((t2 * s.e23) - ((t4 * s.scalar) + (t5 * s.e12)));
    const double t11 = (t2 * s.e13) - ((t4 * s.e12) - (t5 * s.scalar));
    pga3_Line r;
    r.e01 = (x.e01 + t6) + t6;
    r.e02 = (x.e02 + t7) + t7;
    r.e12 = (x.e12 + t8) + t8;
    r.e03 = (x.e03 + t9) + t9;
    r.e13 = (x.e13 + t10) + t10;
    r.e23 = (x.e23 + t11) + t11;
    return r;
}

/* S x rev(S) for a unit Point S (S rev(S) = 1) and a Motor x; not the action otherwise. */
static inline pga3_Motor pga3_point_apply_unit_motor(pga3_Point s, pga3_Motor x) {
    const double t0 = s.e123 * x.e0123;
    const double t1 = -((s.e013 * x.e23) - ((s.e023 * x.e13) - (s.e123 * x.e03)));
    const double t2 = (s.e012 * x.e23) - ((s.e023 * x.e12) - (s.e123 * x.e02));
    const double t3 = -((s.e012 * x.e13) - ((s.e013 * x.e12) - (s.e123 * x.e01)));
    const double t4 = t3 * s.e123;
    const double t5 = -(t2 * s.e123);
    const double t6 = t1 * s.e123;
    const double t7 = -(t0 * s.e123);
    pga3_Motor r;
    r.scalar = x.scalar;
    r.e01 = (x.e01 + t4) + t4;
    r.e02 = (x.e02 + t5) + t5;
    r.e12 = x.e12;
    r.e03 = (x.e03 + t6) + t6;
    r.e13 = x.e13;
    r.e23 = x.e23;
    r.e0123 = (x.e0123 + t7) + t7;
    return r;
}

/* S x rev(S) for a unit Point S (S rev(S) = 1) and a Point x; not the action otherwise. */
static inline pga3_Point pga3_point_apply_unit_point(pga3_Point s, pga3_Point x) {
    const double t0 = -((s.e023 * x.e123) - (s.e123 * x.e023));
    const double t1 = (s.e013 * x.e123) - (s.e123 * x.e013);
    const double t2 = -((s.e012 * x.e123) - (s.e123 * x.e012));
    const double t3 = -(t2 * s.e123);
    const double t4 = t1 * s.e123;
    const double t5 = -(t0 * s.e123);
    pga3_Point r;
    r.e012 = (x.e012 + t3) + t3;
    r.e013 = (x.e013 + t4) + t4;
    r.e023 = (x.e023 + t5) + t5;
    r.e123 = x.e123;
    return r;
}

/* S x rev(S) for a unit Point S (S rev(S) = 1) and a Line x; not the action otherwise. */
static inline pga3_Line pga3_point_apply_unit_line(pga3_Point s, pga3_Line x) {
    const double t0 = -((s.e013 * x.e23) - ((s.e023 * x.e13) - (s.e123 * x.e03)));
    const double t1 = (s.e012 * x.e23) - ((s.e023 * x.e12) - (s.e123 * x.e02));
    const double t2 = -((s.e012 * x.e13) - ((s.e013 * x.e12) - (s.e123 * x.e01)));
    const double t3 = t2 * s.e123;
    const double t4 = -(t1 * s.e123);
    const double t5 = t0 * s.e123;
    pga3_Line r;
    r.e01 = (x.e01 + t3) + t3;
    r.e02 = (x.e02 + t4) + t4;
    r.e12 = x.e12;
    r.e03 = (x.e03 + t5) + t5;
    r.e13 = x.e13;
    r.e23 = x.e23;
    return r;
}

/* S x rev(S) for a unit Line S (S rev(S) = 1) and a Motor x; not the action otherwise. */
static inline pga3_Motor pga3_line_apply_unit_motor(pga3_Line s, pga3_Motor x) {
    const double t0 = -(((s.e02 * x.e12) - (s.e12 * x.e02)) + ((s.e03 * x.e13) - (s.e13 * x.e03)));
    const double t1 = ((s.e01 * x.e12) - (s.e12 * x.e01)) - ((s.e03 * x.e23) - (s.e23 * x.e03));
    const double t2 = -((s.e13 * x.e23) - (s.e23 * x.e13));
    const double t3 = ((s.e01 * x.e13) + (s.e02 * x.e23)) - ((s.e13 * x.e01) + (s.e23 * x.e02));
    const double t4 = (s.e12 * x.e23) - (s.e23 * x.e12);
    const double t5 = -((s.e12 * x.e13) - (s.e13 * x.e12));
    const double t6 = ((t1 * s.e12) - (t2 * s.e02)) + ((t3 * s.e13) - (t4 * s.e03));
    const double t7 = -(((t0 * s.e12) - (t2 * s.e01)) - ((t3 * s.e23) - (t5 * s.e03)));
    const double t8 = (t4 * s.e23) - (t5 * s.e13);
    const double t9 = -(((t0 * s.e13) + (t1 * s.e23)) - ((t4 * s.e01) + (t5 * s.e02)));
    const double t10 = -((t2 * s.e23) - (t5 * s.e12));
    const double t11 = (t2 * s.e13) - (t4 * s.e12);
    pga3_Motor r;
    r.scalar = x.scalar;
    r.e01 = (x.e01 + t6) + t6;
    r.e02 = (x.e02 + t7) + t7;
    r.e12 = (x.e12 + t8) + t8;
    r.e03 = (x.e03 + t9) + t9;
    r.e13 = (x.e13 + t10) + t10;
    r.e23 = (x.e23 + t11) + t11;
    r.e0123 = x.e0123;
    return r;
}

/* S x rev(S) for a unit Line S (S rev(S) = 1) and a Point x; not the action otherwise. */
static inline pga3_Point pga3_line_apply_unit_point(pga3_Line s, pga3_Point x) {
    const double t0 = (s.e03 * x.e123) - ((s.e13 * x.e023) - (s.e23 * x.e013));
    const double t1 = -((s.e02 * x.e123) - ((s.e12 * x.e023) - (s.e23 * x.e012)));
    const double t2 = (s.e01 * x.e123) - ((s.e12 * x.e013) - (s.e13 * x.e012));
    const double t3 = (t1 * s.e23) - (t2 * s.e13);
    const double t4 = -((t0 * s.e23) - (t2 * s.e12));
    const double t5 = (t0 * s.e13) - (t1 * s.e12);
    pga3_Point r;
    r.e012 = (x.e012 + t3) + t3;
    r.e013 = (x.e013 + t4) + t4;
    r.e023 = (x.e023 + t5) + t5;
    r.e123 = x.e123;
    return r;
}

/* S x rev(S) for a unit Line S (S rev(S) = 1) and a Line x; not the action otherwise. */
static inline pga3_Line pga3_line_apply_unit_line(pga3_Line s, pga3_Line x) {
    const double t0 = -(((s.e02 * x.e12) - (s.e12 * x.e02)) + ((s.e03 * x.e13) - (s.e13 * x.e03)));
    const double t1 = ((s.e01 * x.e12) - (s.e12 * x.e01)) - ((s.e03 * x.e23) - (s.e23 * x.e03));
    const double t2 = -((s.e13 * x.e23) - (s.e23 * x.e13));
    const double t3 = ((s.e01 * x.e13) + (s.e02 * x.e23)) - ((s.e13 * x.e01) + (s.e23 * x.e02));
    const double t4 = (s.e12 * x.e23) - (s.e23 * x.e12);
    const double t5 = -((s.e12 * x.e13) - (s.e13 * x.e12));
    const double t6 = ((t1 * s.e12) - (t2 * s.e02)) + ((t3 * s.e13) - (t4 * s.e03));
    const double t7 = -(((t0 * s.e12) - (t2 * s.e01)) - ((t3 * s.e23) - (t5 * s.e03)));
    const double t8 = (t4 * s.e23) - (t5 * s.e13);
    const double t9 = -(((t0 * s.e13) + (t1 * s.e23)) - ((t4 * s.e01) + (t5 * s.e02)));
    const double t10 = -((t2 * s.e23) - (t5 * s.e12));
    const double t11 = (t2 * s.e13) - (t4 * s.e12);
    pga3_Line r;
    r.e01 = (x.e01 + t6) + t6;
    r.e02 = (x.e02 + t7) + t7;
    r.e12 = (x.e12 + t8) + t8;
    r.e03 = (x.e03 + t9) + t9;
    r.e13 = (x.e13 + t10) + t10;
    r.e23 = (x.e23 + t11) + t11;
    return r;
}

/* exp of a Line: a unit Motor (closed form; non-finite input gives non-finite output). */
static inline pga3_Motor pga3_line_exp(pga3_Line x) {
    const double t0 = ((x.e12 * x.e12) + (x.e13 * x.e13)) + (x.e23 * x.e23);
    const pga3_Triple t1 = pga3_exp_factors(t0);
    const double t2 = ((x.e01 * x.e23) - (x.e02 * x.e13)) + (x.e12 * x.e03);
    const double t3 = t2 * t1.y;
    pga3_Motor r;
    r.scalar = t1.z;
    r.e01 = (t1.x * x.e01) + (t3 * x.e23);
    r.e02 = (t1.x * x.e02) - (t3 * x.e13);
    r.e12 = t1.x * x.e12;
    r.e03 = (t1.x * x.e03) + (t3 * x.e12);
    r.e13 = t1.x * x.e13;
    r.e23 = t1.x * x.e23;
    r.e0123 = t2 * t1.x;
    return r;
}

/* log of a unit Motor (m rev(m) = 1): the Line B with exp(B) = m, angle in [0, pi); a full turn gives non-finite output. */
static inline pga3_Line pga3_motor_log_unit(pga3_Motor x) {
    const double t0 = sqrt(((x.e12 * x.e12) + (x.e13 * x.e13)) + (x.e23 * x.e23));
    const pga3_Triple t1 = pga3_log_factors(t0, x.scalar);
    const double t2 = x.e0123 * t1.y;
    pga3_Line r;
    r.e01 = (t1.x * x.e01) - (t2 * x.e23);
    r.e02 = (t1.x * x.e02) + (t2 * x.e13);
    r.e12 = t1.x * x.e12;
    r.e03 = (t1.x * x.e03) - (t2 * x.e12);
    r.e13 = t1.x * x.e13;
    r.e23 = t1.x * x.e23;
    return r;
}

/* m / sqrt(m rev(m)) for a Motor: a unit Motor; a non-positive norm gives non-finite output. */
static inline pga3_Motor pga3_motor_normalize(pga3_Motor x) {
    const double t0 = (x.scalar * x.scalar) - (((-(x.e12 * x.e12)) - (x.e13 * x.e13)) - (x.e23 * x.e23));
    const double t1 = 1.0 / t0;
    const double t2 = (x.scalar * x.e0123) - (((x.e01 * x.e23) - (x.e02 * x.e13)) + (x.e12 * x.e03));
    const double t3 = sqrt(t1);
    const double t4 = (-(t2 * t3)) * t1;
    pga3_Motor r;
    r.scalar = x.scalar * t3;
    r.e01 = (x.e01 * t3) + (-(t4 * x.e23));
    r.e02 = (x.e02 * t3) + (t4 * x.e13);
    r.e12 = x.e12 * t3;
    r.e03 = (x.e03 * t3) + (-(t4 * x.e12));
    r.e13 = x.e13 * t3;
    r.e23 = x.e23 * t3;
    r.e0123 = (x.e0123 * t3) + (x.scalar * t4);
    return r;
}

/* Motor: the coefficients of scalar, e01, e02, e12, e03, e13, e23, e0123. */
typedef struct pga3_Motorf {
    float scalar;
    float e01;
    float e02;
    float e12;
    float e03;
    float e13;
    float e23;
    float e0123;
} pga3_Motorf;

/* Point: the coefficients of e012, e013, e023, e123. */
typedef struct pga3_Pointf {
    float e012;
    float e013;
    float e023;
    float e123;
} pga3_Pointf;

/* Line: the coefficients of e01, e02, e12, e03, e13, e23. */
typedef struct pga3_Linef {
    float e01;
    float e02;
    float e12;
    float e03;
    float e13;
    float e23;
} pga3_Linef;

/* The odd part of the algebra, declared automatically: some product of the declared types lands here. */
/* Odd: the coefficients of e0, e1, e2, e3, e012, e013, e023, e123. */
typedef struct pga3_Oddf {
    float e0;
    float e1;
    float e2;
    float e3;
    float e012;
    float e013;
    float e023;
    float e123;
} pga3_Oddf;

#include <math.h>

typedef struct pga3_Triplef {
    float x, y, z;
} pga3_Triplef;

/* (sinc t, (cos t - sinc t) / t^2, cos t) from t^2 >= 0 (series below t = 1e-3). */
static inline pga3_Triplef pga3_exp_factorsf(float theta2) {
    const float theta = sqrtf(theta2);
    if (theta < 0.001f) {
        const float t4 = theta2 * theta2;
        { pga3_Triplef out; out.x = (1.0f - 0.16666667f * theta2) + 0.008333334f * t4; out.y = ((-0.33333334f) + 0.033333335f * theta2) - 0.0011904762f * t4; out.z = (1.0f - 0.5f * theta2) + 0.041666668f * t4; return out; }
    } else {
        const float si = sinf(theta);
        const float co = cosf(theta);
        const float inv = 1.0f / theta;
        const float sinc = si * inv;
        { pga3_Triplef out; out.x = sinc; out.y = (co - sinc) * (inv * inv); out.z = co; return out; }
    }
}

/* (t / sin t, (t cos t - sin t) / sin^3 t, 0) from sin t >= 0 and cos t, t = atan2 (series below t = 1e-3). */
static inline pga3_Triplef pga3_log_factorsf(float si, float co) {
    const float theta = atan2f(si, co);
    if (theta < 0.001f) {
        const float t2 = theta * theta;
        const float t4 = t2 * t2;
        { pga3_Triplef out; out.x = (1.0f + 0.16666667f * t2) + 0.019444445f * t4; out.y = ((-0.33333334f) - 0.13333334f * t2) - 0.031746034f * t4; out.z = 0.0f; return out; }
    } else {
        const float r = 1.0f / si;
        const float r2 = r * r;
        { pga3_Triplef out; out.x = theta * r; out.y = (theta * co - si) * (r2 * r); out.z = 0.0f; return out; }
    }
}

/* `gp` of a Motor and a Motor. */
static inline pga3_Motorf pga3_motor_gp_motorf(pga3_Motorf a, pga3_Motorf b) {
    const float t0 = a.scalar * b.scalar;
    const float t1 = a.scalar * b.e01;
    const float t2 = a.scalar * b.e02;
    const float t3 = a.scalar * b.e12;
    const float t4 = a.scalar * b.e03;
    const float t5 = a.scalar * b.e13;
    const float t6 = a.scalar * b.e23;
    const float t7 = a.scalar * b.e0123;
    const float t8 = a.e01 * b.scalar;
    const float t9 = a.e01 * b.e12;
    const float t10 = a.e01 * b.e13;
    const float t11 = a.e01 * b.e23;
    const float t12 = a.e02 * b.scalar;
    const float t13 = a.e02 * b.e12;
    const float t14 = a.e02 * b.e13;
    const float t15 = a.e02 * b.e23;
    const float t16 = a.e12 * b.scalar;
    const float t17 = a.e12 * b.e01;
    const float t18 = a.e12 * b.e02;
    const float t19 = a.e12 * b.e12;
    const float t20 = a.e12 * b.e03;
    const float t21 = a.e12 * b.e13;
    const float t22 = a.e12 * b.e23;
    const float t23 = a.e12 * b.e0123;
    const float t24 = a.e03 * b.scalar;
    const float t25 = a.e03 * b.e12;
    const float t26 = a.e03 * b.e13;
    const float t27 = a.e03 * b.e23;
    const float t28 = a.e13 * b.scalar;
    const float t29 = a.e13 * b.e01;
    const float t30 = a.e13 * b.e02;
    const float t31 = a.e13 * b.e12;
    const float t32 = a.e13 * b.e03;
    const float t33 = a.e13 * b.e13;
    const float t34 = a.e13 * b.e23;
    const float t35 = a.e13 * b.e0123;
    const float t36 = a.e23 * b.scalar;
    const float t37 = a.e23 * b.e01;
    const float t38 = a.e23 * b.e02;
    const float t39 = a.e23 * b.e12;
    const float t40 = a.e23 * b.e03;
    const float t41 = a.e23 * b.e13;
    const float t42 = a.e23 * b.e23;
    const float t43 = a.e23 * b.e0123;
    const float t44 = a.e0123 * b.scalar;
    const float t45 = a.e0123 * b.e12;
    const float t46 = a.e0123 * b.e13;
    const float t47 = a.e0123 * b.e23;
    pga3_Motorf r;
    r.scalar = ((t0 - t19) - t33) - t42;
    r.e01 = (((t1 + t8) - t13) + t18) - (((t26 - t32) + t43) + t47);
    r.e02 = (((t2 + t9) + t12) - t17) - (((t27 - t35) - t40) - t46);
    r.e12 = ((t3 + t16) - t34) + t41;
    r.e03 = (((t4 + t10) + t15) - t23) + (((t24 - t29) - t38) - t45);
    r.e13 = ((t5 + t22) + t28) - t39;
    r.e23 = ((t6 - t21) + t31) + t36;
    r.e0123 = (((t7 + t11) - t14) + t20) + (((t25 - t30) + t37) + t44);
    return r;
}

/* `gp` of a Motor and a Point. */
static inline pga3_Oddf pga3_motor_gp_pointf(pga3_Motorf a, pga3_Pointf b) {
    const float t0 = a.scalar * b.e012;
    const float t1 = a.scalar * b.e013;
    const float t2 = a.scalar * b.e023;
    const float t3 = a.scalar * b.e123;
    const float t4 = a.e01 * b.e123;
    const float t5 = a.e02 * b.e123;
    const float t6 = a.e12 * b.e012;
    const float t7 = a.e12 * b.e013;
    const float t8 = a.e12 * b.e023;
    const float t9 = a.e12 * b.e123;
    const float t10 = a.e03 * b.e123;
    const float t11 = a.e13 * b.e012;
    const float t12 = a.e13 * b.e013;
    const float t13 = a.e13 * b.e023;
    const float t14 = a.e13 * b.e123;
    const float t15 = a.e23 * b.e012;
    const float t16 = a.e23 * b.e013;
    const float t17 = a.e23 * b.e023;
    const float t18 = a.e23 * b.e123;
    const float t19 = a.e0123 * b.e123;
    pga3_Oddf r;
    r.e0 = (((-t6) - t12) - t17) - t19;
    r.e1 = -t18;
    r.e2 = t14;
    r.e3 = -t9;
    r.e012 = ((t0 + t10) - t13) + t16;
    r.e013 = ((t1 - t5) + t8) - t15;
    r.e023 = ((t2 + t4) - t7) + t11;
    r.e123 = t3;
    return r;
}

/* `gp` of a Motor and a Line. */
static inline pga3_Motorf pga3_motor_gp_linef(pga3_Motorf a, pga3_Linef b) {
    const float t0 = a.scalar * b.e01;
    const float t1 = a.scalar * b.e02;
    const float t2 = a.scalar * b.e12;
    const float t3 = a.scalar * b.e03;
    const float t4 = a.scalar * b.e13;
    const float t5 = a.scalar * b.e23;
    const float t6 = a.e01 * b.e12;
    const float t7 = a.e01 * b.e13;
    const float t8 = a.e01 * b.e23;
    const float t9 = a.e02 * b.e12;
    const float t10 = a.e02 * b.e13;
    const float t11 = a.e02 * b.e23;
    const float t12 = a.e12 * b.e01;
    const float t13 = a.e12 * b.e02;
    const float t14 = a.e12 * b.e12;
    const float t15 = a.e12 * b.e03;
    const float t16 = a.e12 * b.e13;
    const float t17 = a.e12 * b.e23;
    const float t18 = a.e03 * b.e12;
    const float t19 = a.e03 * b.e13;
    const float t20 = a.e03 * b.e23;
    const float t21 = a.e13 * b.e01;
    const float t22 = a.e13 * b.e02;
    const float t23 = a.e13 * b.e12;
    const float t24 = a.e13 * b.e03;
    const float t25 = a.e13 * b.e13;
    const float t26 = a.e13 * b.e23;
    const float t27 = a.e23 * b.e01;
    const float t28 = a.e23 * b.e02;
    const float t29 = a.e23 * b.e12;
    const float t30 = a.e23 * b.e03;
    const float t31 = a.e23 * b.e13;
    const float t32 = a.e23 * b.e23;
    const float t33 = a.e0123 * b.e12;
    const float t34 = a.e0123 * b.e13;
    const float t35 = a.e0123 * b.e23;
    pga3_Motorf r;
    r.scalar = ((-t14) - t25) - t32;
    r.e01 = (((t0 - t9) + t13) - t19) + (t24 - t35);
    r.e02 = (((t1 + t6) - t12) - t20) + (t30 + t34);
    r.e12 = (t2 - t26) + t31;
    r.e03 = (((t3 + t7) + t11) - t21) - (t28 + t33);
    r.e13 = (t4 + t17) - t29;
    r.e23 = (t5 - t16) + t23;
    r.e0123 = (((t8 - t10) + t15) + t18) - (t22 - t27);
    return r;
}

/* `gp` of a Point and a Motor. */
static inline pga3_Oddf pga3_point_gp_motorf(pga3_Pointf a, pga3_Motorf b) {
    const float t0 = a.e012 * b.scalar;
    const float t1 = a.e012 * b.e12;
    const float t2 = a.e012 * b.e13;
    const float t3 = a.e012 * b.e23;
    const float t4 = a.e013 * b.scalar;
    const float t5 = a.e013 * b.e12;
    const float t6 = a.e013 * b.e13;
    const float t7 = a.e013 * b.e23;
    const float t8 = a.e023 * b.scalar;
    const float t9 = a.e023 * b.e12;
    const float t10 = a.e023 * b.e13;
    const float t11 = a.e023 * b.e23;
    const float t12 = a.e123 * b.scalar;
    const float t13 = a.e123 * b.e01;
    const float t14 = a.e123 * b.e02;
    const float t15 = a.e123 * b.e12;
    const float t16 = a.e123 * b.e03;
    const float t17 = a.e123 * b.e13;
    const float t18 = a.e123 * b.e23;
    const float t19 = a.e123 * b.e0123;
    pga3_Oddf r;
    r.e0 = ((t19 - t6) - t11) - t1;
    r.e1 = -t18;
    r.e2 = t17;
    r.e3 = -t15;
    r.e012 = ((t0 - t7) + t10) - t16;
    r.e013 = ((t3 + t4) - t9) + t14;
    r.e023 = ((t5 - t2) + t8) - t13;
    r.e123 = t12;
    return r;
}

/* `gp` of a Point and a Point. */
static inline pga3_Motorf pga3_point_gp_pointf(pga3_Pointf a, pga3_Pointf b) {
    const float t0 = a.e012 * b.e123;
    const float t1 = a.e013 * b.e123;
    const float t2 = a.e023 * b.e123;
    const float t3 = a.e123 * b.e012;
    const float t4 = a.e123 * b.e013;
    const float t5 = a.e123 * b.e023;
    const float t6 = a.e123 * b.e123;
    pga3_Motorf r;
    r.scalar = -t6;
    r.e01 = t5 - t2;
    r.e02 = t1 - t4;
    r.e12 = 0.0f;
    r.e03 = t3 - t0;
    r.e13 = 0.0f;
    r.e23 = 0.0f;
    r.e0123 = 0.0f;
    return r;
}

/* `gp` of a Point and a Line. */
static inline pga3_Oddf pga3_point_gp_linef(pga3_Pointf a, pga3_Linef b) {
    const float t0 = a.e012 * b.e12;
    const float t1 = a.e012 * b.e13;
    const float t2 = a.e012 * b.e23;
    const float t3 = a.e013 * b.e12;
    const float t4 = a.e013 * b.e13;
    const float t5 = a.e013 * b.e23;
    const float t6 = a.e023 * b.e12;
    const float t7 = a.e023 * b.e13;
    const float t8 = a.e023 * b.e23;
    const float t9 = a.e123 * b.e01;
    const float t10 = a.e123 * b.e02;
    const float t11 = a.e123 * b.e12;
    const float t12 = a.e123 * b.e03;
    const float t13 = a.e123 * b.e13;
    const float t14 = a.e123 * b.e23;
    pga3_Oddf r;
    r.e0 = ((-t0) - t4) - t8;
    r.e1 = -t14;
    r.e2 = t13;
    r.e3 = -t11;
    r.e012 = (t7 - t5) - t12;
    r.e013 = (t2 - t6) + t10;
    r.e023 = (t3 - t1) - t9;
    r.e123 = 0.0f;
    return r;
}

/* `gp` of a Line and a Motor. */
static inline pga3_Motorf pga3_line_gp_motorf(pga3_Linef a, pga3_Motorf b) {
    const float t0 = a.e01 * b.scalar;
    const float t1 = a.e01 * b.e12;
    const float t2 = a.e01 * b.e13;
    const float t3 = a.e01 * b.e23;
    const float t4 = a.e02 * b.scalar;
    const float t5 = a.e02 * b.e12;
    const float t6 = a.e02 * b.e13;
    const float t7 = a.e02 * b.e23;
    const float t8 = a.e12 * b.scalar;
    const float t9 = a.e12 * b.e01;
    const float t10 = a.e12 * b.e02;
    const float t11 = a.e12 * b.e12;
    const float t12 = a.e12 * b.e03;
    const float t13 = a.e12 * b.e13;
    const float t14 = a.e12 * b.e23;
    const float t15 = a.e12 * b.e0123;
    const float t16 = a.e03 * b.scalar;
    const float t17 = a.e03 * b.e12;
    const float t18 = a.e03 * b.e13;
    const float t19 = a.e03 * b.e23;
    const float t20 = a.e13 * b.scalar;
    const float t21 = a.e13 * b.e01;
    const float t22 = a.e13 * b.e02;
    const float t23 = a.e13 * b.e12;
    const float t24 = a.e13 * b.e03;
    const float t25 = a.e13 * b.e13;
    const float t26 = a.e13 * b.e23;
    const float t27 = a.e13 * b.e0123;
    const float t28 = a.e23 * b.scalar;
    const float t29 = a.e23 * b.e01;
    const float t30 = a.e23 * b.e02;
    const float t31 = a.e23 * b.e12;
    const float t32 = a.e23 * b.e03;
    const float t33 = a.e23 * b.e13;
    const float t34 = a.e23 * b.e23;
    const float t35 = a.e23 * b.e0123;
    pga3_Motorf r;
    r.scalar = ((-t11) - t25) - t34;
    r.e01 = (((t0 - t5) + t10) - t18) + (t24 - t35);
    r.e02 = (((t1 + t4) - t9) - t19) + (t27 + t32);
    r.e12 = (t8 - t26) + t33;
    r.e03 = (((t2 + t7) - t15) + t16) - (t21 + t30);
    r.e13 = (t14 + t20) - t31;
    r.e23 = (t23 - t13) + t28;
    r.e0123 = (((t3 - t6) + t12) + t17) - (t22 - t29);
    return r;
}

/* `gp` of a Line and a Point. */
static inline pga3_Oddf pga3_line_gp_pointf(pga3_Linef a, pga3_Pointf b) {
    const float t0 = a.e01 * b.e123;
    const float t1 = a.e02 * b.e123;
    const float t2 = a.e12 * b.e012;
    const float t3 = a.e12 * b.e013;
    const float t4 = a.e12 * b.e023;
    const float t5 = a.e12 * b.e123;
    const float t6 = a.e03 * b.e123;
    const float t7 = a.e13 * b.e012;
    const float t8 = a.e13 * b.e013;
    const float t9 = a.e13 * b.e023;
    const float t10 = a.e13 * b.e123;
    const float t11 = a.e23 * b.e012;
    const float t12 = a.e23 * b.e013;
    const float t13 = a.e23 * b.e023;
    const float t14 = a.e23 * b.e123;
    pga3_Oddf r;
    r.e0 = ((-t2) - t8) - t13;
    r.e1 = -t14;
    r.e2 = t10;
    r.e3 = -t5;
    r.e012 = (t6 - t9) + t12;
    r.e013 = (t4 - t1) - t11;
    r.e023 = (t0 - t3) + t7;
    r.e123 = 0.0f;
    return r;
}

/* `gp` of a Line and a Line. */
static inline pga3_Motorf pga3_line_gp_linef(pga3_Linef a, pga3_Linef b) {
    const float t0 = a.e01 * b.e12;
    const float t1 = a.e01 * b.e13;
    const float t2 = a.e01 * b.e23;
    const float t3 = a.e02 * b.e12;
    const float t4 = a.e02 * b.e13;
    const float t5 = a.e02 * b.e23;
    const float t6 = a.e12 * b.e01;
    const float t7 = a.e12 * b.e02;
    const float t8 = a.e12 * b.e12;
    const float t9 = a.e12 * b.e03;
    const float t10 = a.e12 * b.e13;
    const float t11 = a.e12 * b.e23;
    const float t12 = a.e03 * b.e12;
    const float t13 = a.e03 * b.e13;
    const float t14 = a.e03 * b.e23;
    const float t15 = a.e13 * b.e01;
    const float t16 = a.e13 * b.e02;
    const float t17 = a.e13 * b.e12;
    const float t18 = a.e13 * b.e03;
    const float t19 = a.e13 * b.e13;
    const float t20 = a.e13 * b.e23;
    const float t21 = a.e23 * b.e01;
    const float t22 = a.e23 * b.e02;
    const float t23 = a.e23 * b.e12;
    const float t24 = a.e23 * b.e03;
    const float t25 = a.e23 * b.e13;
    const float t26 = a.e23 * b.e23;
    pga3_Motorf r;
    r.scalar = ((-t8) - t19) - t26;
    r.e01 = ((t7 - t3) - t13) + t18;
    r.e02 = ((t0 - t6) - t14) + t24;
    r.e12 = t25 - t20;
    r.e03 = ((t1 + t5) - t15) - t22;
    r.e13 = t11 - t23;
    r.e23 = t17 - t10;
    r.e0123 = (((t2 - t4) + t9) + t12) - (t16 - t21);
    return r;
}

/* The reverse of a Motor. */
static inline pga3_Motorf pga3_motor_reversef(pga3_Motorf x) {
    pga3_Motorf r;
    r.scalar = x.scalar;
    r.e01 = -x.e01;
    r.e02 = -x.e02;
    r.e12 = -x.e12;
    r.e03 = -x.e03;
    r.e13 = -x.e13;
    r.e23 = -x.e23;
    r.e0123 = x.e0123;
    return r;
}

/* The squared norm <x rev(x)>_0 of a Motor (may be negative or zero). */
static inline float pga3_motor_norm_squaredf(pga3_Motorf x) {
    const float t0 = x.scalar * x.scalar;
    const float t1 = x.e12 * x.e12;
    const float t2 = x.e13 * x.e13;
    const float t3 = x.e23 * x.e23;
    return ((t0 + t1) + t2) + t3;
}

/* The reverse of a Point. */
static inline pga3_Pointf pga3_point_reversef(pga3_Pointf x) {
    pga3_Pointf r;
    r.e012 = -x.e012;
    r.e013 = -x.e013;
    r.e023 = -x.e023;
    r.e123 = -x.e123;
    return r;
}

/* The squared norm <x rev(x)>_0 of a Point (may be negative or zero). */
static inline float pga3_point_norm_squaredf(pga3_Pointf x) {
    const float t0 = x.e123 * x.e123;
    return t0;
}

/* The reverse of a Line. */
static inline pga3_Linef pga3_line_reversef(pga3_Linef x) {
    pga3_Linef r;
    r.e01 = -x.e01;
    r.e02 = -x.e02;
    r.e12 = -x.e12;
    r.e03 = -x.e03;
    r.e13 = -x.e13;
    r.e23 = -x.e23;
    return r;
}

/* The squared norm <x rev(x)>_0 of a Line (may be negative or zero). */
static inline float pga3_line_norm_squaredf(pga3_Linef x) {
    const float t0 = x.e12 * x.e12;
    const float t1 = x.e13 * x.e13;
    const float t2 = x.e23 * x.e23;
    return (t0 + t1) + t2;
}

/* S x rev(S) for a Motor S and a Motor x, in one fused kernel. */
static inline pga3_Motorf pga3_motor_apply_motorf(pga3_Motorf s, pga3_Motorf x) {
    const float t0 = ((s.scalar * x.scalar) - (s.e12 * x.e12)) - ((s.e13 * x.e13) + (s.e23 * x.e23));
    const float t1 = (((s.scalar * x.e01) + (s.e01 * x.scalar)) - ((s.e02 * x.e12) - (s.e12 * x.e02))) - (((s.e03 * x.e13) - (s.e13 * x.e03)) + ((s.e23 * x.e0123) + (s.e0123 * x.e23)));
    const float t2 = (((s.scalar * x.e02) + (s.e01 * x.e12)) + ((s.e02 * x.scalar) - (s.e12 * x.e01))) - (((s.e03 * x.e23) - (s.e13 * x.e0123)) - ((s.e23 * x.e03) + (s.e0123 * x.e13)));
    const float t3 = ((s.scalar * x.e12) + (s.e12 * x.scalar)) - ((s.e13 * x.e23) - (s.e23 * x.e13));
    const float t4 = (((s.scalar * x.e03) + (s.e01 * x.e13)) + ((s.e02 * x.e23) - (s.e12 * x.e0123))) + (((s.e03 * x.scalar) - (s.e13 * x.e01)) - ((s.e23 * x.e02) + (s.e0123 * x.e12)));
    const float t5 = ((s.scalar * x.e13) + (s.e12 * x.e23)) + ((s.e13 * x.scalar) - (s.e23 * x.e12));
    const float t6 = ((s.scalar * x.e23) - (s.e12 * x.e13)) + ((s.e13 * x.e12) + (s.e23 * x.scalar));
    const float t7 = (((s.scalar * x.e0123) + (s.e01 * x.e23)) - ((s.e02 * x.e13) - (s.e12 * x.e03))) + (((s.e03 * x.e12) - (s.e13 * x.e02)) + ((s.e23 * x.e01) + (s.e0123 * x.scalar)));
    pga3_Motorf r;
    r.scalar = ((t0 * s.scalar) + (t3 * s.e12)) + ((t5 * s.e13) + (t6 * s.e23));
    r.e01 = (((t1 * s.scalar) - (t0 * s.e01)) - ((t3 * s.e02) - (t2 * s.e12))) - (((t5 * s.e03) - (t4 * s.e13)) - ((t7 * s.e23) - (t6 * s.e0123)));
    r.e02 = (((t2 * s.scalar) + (t3 * s.e01)) - ((t0 * s.e02) + (t1 * s.e12))) - (((t6 * s.e03) + (t7 * s.e13)) - ((t4 * s.e23) + (t5 * s.e0123)));
    r.e12 = ((t3 * s.scalar) - (t0 * s.e12)) - ((t6 * s.e13) - (t5 * s.e23));
    r.e03 = (((t4 * s.scalar) + (t5 * s.e01)) + ((t6 * s.e02) + (t7 * s.e12))) - (((t0 * s.e03) + (t1 * s.e13)) + ((t2 * s.e23) + (t3 * s.e0123)));
    r.e13 = ((t5 * s.scalar) + (t6 * s.e12)) - ((t0 * s.e13) + (t3 * s.e23));
    r.e23 = ((t6 * s.scalar) - (t5 * s.e12)) + ((t3 * s.e13) - (t0 * s.e23));
    r.e0123 = (((t7 * s.scalar) - (t6 * s.e01)) + ((t5 * s.e02) - (t4 * s.e12))) - (((t3 * s.e03) - (t2 * s.e13)) + ((t1 * s.e23) - (t0 * s.e0123)));
    return r;
}

/* S x rev(S) for a Motor S and a Point x, in one fused kernel. */
static inline pga3_Pointf pga3_motor_apply_pointf(pga3_Motorf s, pga3_Pointf x) {
    const float t0 = (-s.e0123) * x.e123;
    const float t1 = (s.e03 * x.e123) - ((s.e13 * x.e023) + ((-s.e23) * x.e013));
    const float t2 = -((s.e02 * x.e123) - ((s.e12 * x.e023) + ((-s.e23) * x.e012)));
    const float t3 = (s.e01 * x.e123) - ((s.e12 * x.e013) - (s.e13 * x.e012));
    const float t4 = ((s.scalar * s.scalar) + (s.e23 * s.e23)) + ((s.e12 * s.e12) + (s.e13 * s.e13));
    const float t5 = (((t1 * s.scalar) - (t0 * s.e12)) - (t3 * s.e13)) - (t2 * (-s.e23));
    const float t6 = (((t2 * s.scalar) + (t3 * s.e12)) + (t1 * (-s.e23))) - (t0 * s.e13);
    const float t7 = (((t3 * s.scalar) + (t1 * s.e13)) + (t0 * (-s.e23))) - (t2 * s.e12);
    pga3_Pointf r;
    r.e012 = (t4 * x.e012) + (t5 + t5);
    r.e013 = (t4 * x.e013) + (t6 + t6);
    r.e023 = (t4 * x.e023) + (t7 + t7);
    r.e123 = t4 * x.e123;
    return r;
}

/* S x rev(S) for a Motor S and a Line x, in one fused kernel. */
static inline pga3_Linef pga3_motor_apply_linef(pga3_Motorf s, pga3_Linef x) {
    const float t0 = -((s.e12 * x.e12) + ((s.e13 * x.e13) + (s.e23 * x.e23)));
    const float t1 = ((s.scalar * x.e01) - ((s.e02 * x.e12) - (s.e12 * x.e02))) - ((s.e03 * x.e13) - ((s.e13 * x.e03) - (s.e0123 * x.e23)));
    const float t2 = ((s.scalar * x.e02) + ((s.e01 * x.e12) - (s.e12 * x.e01))) - ((s.e03 * x.e23) - ((s.e23 * x.e03) + (s.e0123 * x.e13)));
    const float t3 = (s.scalar * x.e12) - ((s.e13 * x.e23) - (s.e23 * x.e13));
    const float t4 = ((s.scalar * x.e03) + ((s.e01 * x.e13) + (s.e02 * x.e23))) - ((s.e13 * x.e01) + ((s.e23 * x.e02) + (s.e0123 * x.e12)));
    const float t5 = (s.scalar * x.e13) + ((s.e12 * x.e23) - (s.e23 * x.e12));
    const float t6 = (s.scalar * x.e23) - ((s.e12 * x.e13) - (s.e13 * x.e12));
    const float t7 = ((s.e01 * x.e23) - ((s.e02 * x.e13) - (s.e12 * x.e03))) + ((s.e03 * x.e12) - ((s.e13 * x.e02) - (s.e23 * x.e01)));
    pga3_Linef r;
    r.e01 = (((t1 * s.scalar) - (t0 * s.e01)) - ((t3 * s.e02) - (t2 * s.e12))) - (((t5 * s.e03) - (t4 * s.e13)) - ((t7 * s.e23) - (t6 * s.e0123)));
    r.e02 = (((t2 * s.scalar) + (t3 * s.e01)) - ((t0 * s.e02) + (t1 * s.e12))) - (((t6 * s.e03) + (t7 * s.e13)) - ((t4 * s.e23) + (t5 * s.e0123)));
    r.e12 = ((t3 * s.scalar) - (t0 * s.e12)) - ((t6 * s.e13) - (t5 * s.e23));
    r.e03 = (((t4 * s.scalar) + (t5 * s.e01)) + ((t6 * s.e02) + (t7 * s.e12))) - (((t0 * s.e03) + (t1 * s.e13)) + ((t2 * s.e23) + (t3 * s.e0123)));
    r.e13 = ((t5 * s.scalar) + (t6 * s.e12)) - ((t0 * s.e13) + (t3 * s.e23));
    r.e23 = ((t6 * s.scalar) - (t5 * s.e12)) + ((t3 * s.e13) - (t0 * s.e23));
    return r;
}

/* S x rev(S) for a Point S and a Motor x, in one fused kernel. */
static inline pga3_Motorf pga3_point_apply_motorf(pga3_Pointf s, pga3_Motorf x) {
    const float t0 = s.e123 * x.e0123;
    const float t1 = -((s.e013 * x.e23) - ((s.e023 * x.e13) - (s.e123 * x.e03)));
    const float t2 = (s.e012 * x.e23) - ((s.e023 * x.e12) - (s.e123 * x.e02));
    const float t3 = -((s.e012 * x.e13) - ((s.e013 * x.e12) - (s.e123 * x.e01)));
    const float t4 = s.e123 * s.e123;
    const float t5 = t3 * s.e123;
    const float t6 = -(t2 * s.e123);
    const float t7 = t1 * s.e123;
    const float t8 = -(t0 * s.e123);
    pga3_Motorf r;
    r.scalar = t4 * x.scalar;
    r.e01 = (t4 * x.e01) + (t5 + t5);
    r.e02 = (t4 * x.e02) + (t6 + t6);
    r.e12 = t4 * x.e12;
    r.e03 = (t4 * x.e03) + (t7 + t7);
    r.e13 = t4 * x.e13;
    r.e23 = t4 * x.e23;
    r.e0123 = (t4 * x.e0123) + (t8 + t8);
    return r;
}

/* S x rev(S) for a Point S and a Point x, in one fused kernel. */
static inline pga3_Pointf pga3_point_apply_pointf(pga3_Pointf s, pga3_Pointf x) {
    const float t0 = -(s.e123 * x.e123);
    const float t1 = -((s.e023 * x.e123) - (s.e123 * x.e023));
    const float t2 = (s.e013 * x.e123) - (s.e123 * x.e013);
    const float t3 = -((s.e012 * x.e123) - (s.e123 * x.e012));
    pga3_Pointf r;
    r.e012 = -((t0 * s.e012) + (t3 * s.e123));
    r.e013 = (t2 * s.e123) - (t0 * s.e013);
    r.e023 = -((t0 * s.e023) + (t1 * s.e123));
    r.e123 = -(t0 * s.e123);
    return r;
}

/* S x rev(S) for a Point S and a Line x, in one fused kernel. */
static inline pga3_Linef pga3_point_apply_linef(pga3_Pointf s, pga3_Linef x) {
    const float t0 = -(s.e123 * x.e23);
    const float t1 = s.e123 * x.e13;
    const float t2 = -((s.e013 * x.e23) - ((s.e023 * x.e13) - (s.e123 * x.e03)));
    const float t3 = -(s.e123 * x.e12);
    const float t4 = (s.e012 * x.e23) - ((s.e023 * x.e12) - (s.e123 * x.e02));
    const float t5 = -((s.e012 * x.e13) - ((s.e013 * x.e12) - (s.e123 * x.e01)));
    pga3_Linef r;
    r.e01 = (t5 * s.e123) - ((t1 * s.e012) + (t3 * s.e013));
    r.e02 = (t0 * s.e012) - ((t3 * s.e023) + (t4 * s.e123));
    r.e12 = -(t3 * s.e123);
    r.e03 = (t0 * s.e013) + ((t1 * s.e023) + (t2 * s.e123));
    r.e13 = t1 * s.e123;
    r.e23 = -(t0 * s.e123);
    return r;
}

/* S x rev(S) for a Line S and a Motor x, in one fused kernel. */
static inline pga3_Motorf pga3_line_apply_motorf(pga3_Linef s, pga3_Motorf x) {
    const float t0 = -((s.e12 * x.e12) + ((s.e13 * x.e13) + (s.e23 * x.e23)));
    const float t1 = ((s.e01 * x.scalar) - ((s.e02 * x.e12) - (s.e12 * x.e02))) - ((s.e03 * x.e13) - ((s.e13 * x.e03) - (s.e23 * x.e0123)));
    const float t2 = ((s.e01 * x.e12) + ((s.e02 * x.scalar) - (s.e12 * x.e01))) - ((s.e03 * x.e23) - ((s.e13 * x.e0123) + (s.e23 * x.e03)));
    const float t3 = (s.e12 * x.scalar) - ((s.e13 * x.e23) - (s.e23 * x.e13));
    const float t4 = ((s.e01 * x.e13) + ((s.e02 * x.e23) - (s.e12 * x.e0123))) + ((s.e03 * x.scalar) - ((s.e13 * x.e01) + (s.e23 * x.e02)));
    const float t5 = (s.e12 * x.e23) + ((s.e13 * x.scalar) - (s.e23 * x.e12));
    const float t6 = -((s.e12 * x.e13) - ((s.e13 * x.e12) + (s.e23 * x.scalar)));
    const float t7 = ((s.e01 * x.e23) - ((s.e02 * x.e13) - (s.e12 * x.e03))) + ((s.e03 * x.e12) - ((s.e13 * x.e02) - (s.e23 * x.e01)));
    pga3_Motorf r;
    r.scalar = (t3 * s.e12) + ((t5 * s.e13) + (t6 * s.e23));
    r.e01 = ((t2 * s.e12) - ((t0 * s.e01) + (t3 * s.e02))) - ((t5 * s.e03) - ((t4 * s.e13) + (t7 * s.e23)));
    r.e02 = ((t3 * s.e01) - ((t0 * s.e02) + (t1 * s.e12))) - ((t6 * s.e03) + ((t7 * s.e13) - (t4 * s.e23)));
    r.e12 = (t5 * s.e23) - ((t0 * s.e12) + (t6 * s.e13));
    r.e03 = ((t5 * s.e01) + ((t6 * s.e02) + (t7 * s.e12))) - ((t0 * s.e03) + ((t1 * s.e13) + (t2 * s.e23)));
    r.e13 = (t6 * s.e12) - ((t0 * s.e13) + (t3 * s.e23));
    r.e23 = (t3 * s.e13) - ((t5 * s.e12) + (t0 * s.e23));
    r.e0123 = ((t5 * s.e02) - ((t6 * s.e01) + (t4 * s.e12))) - ((t3 * s.e03) - ((t2 * s.e13) - (t1 * s.e23)));
    return r;
}

/* S x rev(S) for a Line S and a Point x, in one fused kernel. */
static inline pga3_Pointf pga3_line_apply_pointf(pga3_Linef s, pga3_Pointf x) {
    const float t0 = (s.e03 * x.e123) - ((s.e13 * x.e023) - (s.e23 * x.e013));
    const float t1 = -((s.e02 * x.e123) - ((s.e12 * x.e023) - (s.e23 * x.e012)));
    const float t2 = (s.e01 * x.e123) - ((s.e12 * x.e013) - (s.e13 * x.e012));
    const float t3 = (s.e12 * s.e12) + ((s.e13 * s.e13) + (s.e23 * s.e23));
    const float t4 = (t1 * s.e23) - (t2 * s.e13);
    const float t5 = (t2 * s.e12) - (t0 * s.e23);
    const float t6 = (t0 * s.e13) - (t1 * s.e12);
    pga3_Pointf r;
    r.e012 = (t3 * x.e012) + (t4 + t4);
    r.e013 = (t3 * x.e013) + (t5 + t5);
    r.e023 = (t3 * x.e023) + (t6 + t6);
    r.e123 = t3 * x.e123;
    return r;
}

/* S x rev(S) for a Line S and a Line x, in one fused kernel. */
static inline pga3_Linef pga3_line_apply_linef(pga3_Linef s, pga3_Linef x) {
    const float t0 = -((s.e12 * x.e12) + ((s.e13 * x.e13) + (s.e23 * x.e23)));
    const float t1 = -(((s.e02 * x.e12) - (s.e12 * x.e02)) + ((s.e03 * x.e13) - (s.e13 * x.e03)));
    const float t2 = ((s.e01 * x.e12) - (s.e12 * x.e01)) - ((s.e03 * x.e23) - (s.e23 * x.e03));
    const float t3 = -((s.e13 * x.e23) - (s.e23 * x.e13));
    const float t4 = ((s.e01 * x.e13) + (s.e02 * x.e23)) - ((s.e13 * x.e01) + (s.e23 * x.e02));
    const float t5 = (s.e12 * x.e23) - (s.e23 * x.e12);
    const float t6 = -((s.e12 * x.e13) - (s.e13 * x.e12));
    const float t7 = ((s.e01 * x.e23) - ((s.e02 * x.e13) - (s.e12 * x.e03))) + ((s.e03 * x.e12) - ((s.e13 * x.e02) - (s.e23 * x.e01)));
    pga3_Linef r;
    r.e01 = ((t2 * s.e12) - ((t0 * s.e01) + (t3 * s.e02))) - ((t5 * s.e03) - ((t4 * s.e13) + (t7 * s.e23)));
    r.e02 = ((t3 * s.e01) - ((t0 * s.e02) + (t1 * s.e12))) - ((t6 * s.e03) + ((t7 * s.e13) - (t4 * s.e23)));
    r.e12 = (t5 * s.e23) - ((t0 * s.e12) + (t6 * s.e13));
    r.e03 = ((t5 * s.e01) + ((t6 * s.e02) + (t7 * s.e12))) - ((t0 * s.e03) + ((t1 * s.e13) + (t2 * s.e23)));
    r.e13 = (t6 * s.e12) - ((t0 * s.e13) + (t3 * s.e23));
    r.e23 = (t3 * s.e13) - ((t5 * s.e12) + (t0 * s.e23));
    return r;
}

/* S x rev(S) for a unit Motor S (S rev(S) = 1) and a Motor x; not the action otherwise. */
static inline pga3_Motorf pga3_motor_apply_unit_motorf(pga3_Motorf s, pga3_Motorf x) {
    const float t0 = -(((s.e02 * x.e12) - (s.e12 * x.e02)) + ((s.e03 * x.e13) - (s.e13 * x.e03)));
    const float t1 = ((s.e01 * x.e12) - (s.e12 * x.e01)) - ((s.e03 * x.e23) - (s.e23 * x.e03));
    const float t2 = -((s.e13 * x.e23) - (s.e23 * x.e13));
    const float t3 = ((s.e01 * x.e13) + (s.e02 * x.e23)) - ((s.e13 * x.e01) + (s.e23 * x.e02));
    const float t4 = (s.e12 * x.e23) - (s.e23 * x.e12);
    const float t5 = -((s.e12 * x.e13) - (s.e13 * x.e12));
    const float t6 = ((t0 * s.scalar) + ((t1 * s.e12) - (t2 * s.e02))) + ((t3 * s.e13) - ((t4 * s.e03) + (t5 * s.e0123)));
    const float t7 = -(((t0 * s.e12) - ((t1 * s.scalar) + (t2 * s.e01))) - ((t3 * s.e23) + ((t4 * s.e0123) - (t5 * s.e03))));
    const float t8 = (t2 * s.scalar) + ((t4 * s.e23) - (t5 * s.e13));
    const float t9 = -(((t0 * s.e13) + ((t1 * s.e23) + (t2 * s.e0123))) - ((t3 * s.scalar) + ((t4 * s.e01) + (t5 * s.e02))));
    const float t10 = -((t2 * s.e23) - ((t4 * s.scalar) + (t5 * s.e12)));
    const float t11 = (t2 * s.e13) - ((t4 * s.e12) - (t5 * s.scalar));
    pga3_Motorf r;
    r.scalar = x.scalar;
    r.e01 = (x.e01 + t6) + t6;
    r.e02 = (x.e02 + t7) + t7;
    r.e12 = (x.e12 + t8) + t8;
    r.e03 = (x.e03 + t9) + t9;
    r.e13 = (x.e13 + t10) + t10;
    r.e23 = (x.e23 + t11) + t11;
    r.e0123 = x.e0123;
    return r;
}

/* S x rev(S) for a unit Motor S (S rev(S) = 1) and a Point x; not the action otherwise. */
static inline pga3_Pointf pga3_motor_apply_unit_pointf(pga3_Motorf s, pga3_Pointf x) {
    const float t0 = -(s.e0123 * x.e123);
    const float t1 = (s.e03 * x.e123) - ((s.e13 * x.e023) - (s.e23 * x.e013));
    const float t2 = -((s.e02 * x.e123) - ((s.e12 * x.e023) - (s.e23 * x.e012)));
    const float t3 = (s.e01 * x.e123) - ((s.e12 * x.e013) - (s.e13 * x.e012));
    const float t4 = -(((t0 * s.e12) - (t1 * s.scalar)) - ((t2 * s.e23) - (t3 * s.e13)));
    const float t5 = -(((t0 * s.e13) + (t1 * s.e23)) - ((t2 * s.scalar) + (t3 * s.e12)));
    const float t6 = -(((t0 * s.e23) - (t1 * s.e13)) + ((t2 * s.e12) - (t3 * s.scalar)));
    pga3_Pointf r;
    r.e012 = (x.e012 + t4) + t4;
    r.e013 = (x.e013 + t5) + t5;
    r.e023 = (x.e023 + t6) + t6;
    r.e123 = x.e123;
    return r;
}

/* S x rev(S) for a unit Motor S (S rev(S) = 1) and a Line x; not the action otherwise. */
static inline pga3_Linef pga3_motor_apply_unit_linef(pga3_Motorf s, pga3_Linef x) {
    const float t0 = -(((s.e02 * x.e12) - (s.e12 * x.e02)) + ((s.e03 * x.e13) - (s.e13 * x.e03)));
    const float t1 = ((s.e01 * x.e12) - (s.e12 * x.e01)) - ((s.e03 * x.e23) - (s.e23 * x.e03));
    const float t2 = -((s.e13 * x.e23) - (s.e23 * x.e13));
    const float t3 = ((s.e01 * x.e13) + (s.e02 * x.e23)) - ((s.e13 * x.e01) + (s.e23 * x.e02));
    const float t4 = (s.e12 * x.e23) - (s.e23 * x.e12);
    const float t5 = -((s.e12 * x.e13) - (s.e13 * x.e12));
    const float t6 = ((t0 * s.scalar) + ((t1 * s.e12) - (t2 * s.e02))) + ((t3 * s.e13) - ((t4 * s.e03) + (t5 * s.e0123)));
    const float t7 = -(((t0 * s.e12) - ((t1 * s.scalar) + (t2 * s.e01))) - ((t3 * s.e23) + ((t4 * s.e0123) - (t5 * s.e03))));
    const float t8 = (t2 * s.scalar) + ((t4 * s.e23) - (t5 * s.e13));
    const float t9 = -(((t0 * s.e13) + ((t1 * s.e23) + (t2 * s.e0123))) - ((t3 * s.scalar) + ((t4 * s.e01) + (t5 * s.e02))));
    const float t10 = -((t2 * s.e23) - ((t4 * s.scalar) + (t5 * s.e12)));
    const float t11 = (t2 * s.e13) - ((t4 * s.e12) - (t5 * s.scalar));
    pga3_Linef r;
    r.e01 = (x.e01 + t6) + t6;
    r.e02 = (x.e02 + t7) + t7;
    r.e12 = (x.e12 + t8) + t8;
    r.e03 = (x.e03 + t9) + t9;
    r.e13 = (x.e13 + t10) + t10;
    r.e23 = (x.e23 + t11) + t11;
    return r;
}

/* S x rev(S) for a unit Point S (S rev(S) = 1) and a Motor x; not the action otherwise. */
static inline pga3_Motorf pga3_point_apply_unit_motorf(pga3_Pointf s, pga3_Motorf x) {
    const float t0 = s.e123 * x.e0123;
    const float t1 = -((s.e013 * x.e23) - ((s.e023 * x.e13) - (s.e123 * x.e03)));
    const float t2 = (s.e012 * x.e23) - ((s.e023 * x.e12) - (s.e123 * x.e02));
    const float t3 = -((s.e012 * x.e13) - ((s.e013 * x.e12) - (s.e123 * x.e01)));
    const float t4 = t3 * s.e123;
    const float t5 = -(t2 * s.e123);
    const float t6 = t1 * s.e123;
    const float t7 = -(t0 * s.e123);
    pga3_Motorf r;
    r.scalar = x.scalar;
    r.e01 = (x.e01 + t4) + t4;
    r.e02 = (x.e02 + t5) + t5;
    r.e12 = x.e12;
    r.e03 = (x.e03 + t6) + t6;
    r.e13 = x.e13;
    r.e23 = x.e23;
    r.e0123 = (x.e0123 + t7) + t7;
    return r;
}

/* S x rev(S) for a unit Point S (S rev(S) = 1) and a Point x; not the action otherwise. */
static inline pga3_Pointf pga3_point_apply_unit_pointf(pga3_Pointf s, pga3_Pointf x) {
    const float t0 = -((s.e023 * x.e123) - (s.e123 * x.e023));
    const float t1 = (s.e013 * x.e123) - (s.e123 * x.e013);
    const float t2 = -((s.e012 * x.e123) - (s.e123 * x.e012));
    const float t3 = -(t2 * s.e123);
    const float t4 = t1 * s.e123;
    const float t5 = -(t0 * s.e123);
    pga3_Pointf r;
    r.e012 = (x.e012 + t3) + t3;
    r.e013 = (x.e013 + t4) + t4;
    r.e023 = (x.e023 + t5) + t5;
    r.e123 = x.e123;
    return r;
}

/* S x rev(S) for a unit Point S (S rev(S) = 1) and a Line x; not the action otherwise. */
static inline pga3_Linef pga3_point_apply_unit_linef(pga3_Pointf s, pga3_Linef x) {
    const float t0 = -((s.e013 * x.e23) - ((s.e023 * x.e13) - (s.e123 * x.e03)));
    const float t1 = (s.e012 * x.e23) - ((s.e023 * x.e12) - (s.e123 * x.e02));
    const float t2 = -((s.e012 * x.e13) - ((s.e013 * x.e12) - (s.e123 * x.e01)));
    const float t3 = t2 * s.e123;
    const float t4 = -(t1 * s.e123);
    const float t5 = t0 * s.e123;
    pga3_Linef r;
    r.e01 = (x.e01 + t3) + t3;
    r.e02 = (x.e02 + t4) + t4;
    r.e12 = x.e12;
    r.e03 = (x.e03 + t5) + t5;
    r.e13 = x.e13;
    r.e23 = x.e23;
    return r;
}

/* S x rev(S) for a unit Line S (S rev(S) = 1) and a Motor x; not the action otherwise. */
static inline pga3_Motorf pga3_line_apply_unit_motorf(pga3_Linef s, pga3_Motorf x) {
    const float t0 = -(((s.e02 * x.e12) - (s.e12 * x.e02)) + ((s.e03 * x.e13) - (s.e13 * x.e03)));
    const float t1 = ((s.e01 * x.e12) - (s.e12 * x.e01)) - ((s.e03 * x.e23) - (s.e23 * x.e03));
    const float t2 = -((s.e13 * x.e23) - (s.e23 * x.e13));
    const float t3 = ((s.e01 * x.e13) + (s.e02 * x.e23)) - ((s.e13 * x.e01) + (s.e23 * x.e02));
    const float t4 = (s.e12 * x.e23) - (s.e23 * x.e12);
    const float t5 = -((s.e12 * x.e13) - (s.e13 * x.e12));
    const float t6 = ((t1 * s.e12) - (t2 * s.e02)) + ((t3 * s.e13) - (t4 * s.e03));
    const float t7 = -(((t0 * s.e12) - (t2 * s.e01)) - ((t3 * s.e23) - (t5 * s.e03)));
    const float t8 = (t4 * s.e23) - (t5 * s.e13);
    const float t9 = -(((t0 * s.e13) + (t1 * s.e23)) - ((t4 * s.e01) + (t5 * s.e02)));
    const float t10 = -((t2 * s.e23) - (t5 * s.e12));
    const float t11 = (t2 * s.e13) - (t4 * s.e12);
    pga3_Motorf r;
    r.scalar = x.scalar;
    r.e01 = (x.e01 + t6) + t6;
    r.e02 = (x.e02 + t7) + t7;
    r.e12 = (x.e12 + t8) + t8;
    r.e03 = (x.e03 + t9) + t9;
    r.e13 = (x.e13 + t10) + t10;
    r.e23 = (x.e23 + t11) + t11;
    r.e0123 = x.e0123;
    return r;
}

/* S x rev(S) for a unit Line S (S rev(S) = 1) and a Point x; not the action otherwise. */
static inline pga3_Pointf pga3_line_apply_unit_pointf(pga3_Linef s, pga3_Pointf x) {
    const float t0 = (s.e03 * x.e123) - ((s.e13 * x.e023) - (s.e23 * x.e013));
    const float t1 = -((s.e02 * x.e123) - ((s.e12 * x.e023) - (s.e23 * x.e012)));
    const float t2 = (s.e01 * x.e123) - ((s.e12 * x.e013) - (s.e13 * x.e012));
    const float t3 = (t1 * s.e23) - (t2 * s.e13);
    const float t4 = -((t0 * s.e23) - (t2 * s.e12));
    const float t5 = (t0 * s.e13) - (t1 * s.e12);
    pga3_Pointf r;
    r.e012 = (x.e012 + t3) + t3;
    r.e013 = (x.e013 + t4) + t4;
    r.e023 = (x.e023 + t5) + t5;
    r.e123 = x.e123;
    return r;
}

/* S x rev(S) for a unit Line S (S rev(S) = 1) and a Line x; not the action otherwise. */
static inline pga3_Linef pga3_line_apply_unit_linef(pga3_Linef s, pga3_Linef x) {
    const float t0 = -(((s.e02 * x.e12) - (s.e12 * x.e02)) + ((s.e03 * x.e13) - (s.e13 * x.e03)));
    const float t1 = ((s.e01 * x.e12) - (s.e12 * x.e01)) - ((s.e03 * x.e23) - (s.e23 * x.e03));
    const float t2 = -((s.e13 * x.e23) - (s.e23 * x.e13));
    const float t3 = ((s.e01 * x.e13) + (s.e02 * x.e23)) - ((s.e13 * x.e01) + (s.e23 * x.e02));
    const float t4 = (s.e12 * x.e23) - (s.e23 * x.e12);
    const float t5 = -((s.e12 * x.e13) - (s.e13 * x.e12));
    const float t6 = ((t1 * s.e12) - (t2 * s.e02)) + ((t3 * s.e13) - (t4 * s.e03));
    const float t7 = -(((t0 * s.e12) - (t2 * s.e01)) - ((t3 * s.e23) - (t5 * s.e03)));
    const float t8 = (t4 * s.e23) - (t5 * s.e13);
    const float t9 = -(((t0 * s.e13) + (t1 * s.e23)) - ((t4 * s.e01) + (t5 * s.e02)));
    const float t10 = -((t2 * s.e23) - (t5 * s.e12));
    const float t11 = (t2 * s.e13) - (t4 * s.e12);
    pga3_Linef r;
    r.e01 = (x.e01 + t6) + t6;
    r.e02 = (x.e02 + t7) + t7;
    r.e12 = (x.e12 + t8) + t8;
    r.e03 = (x.e03 + t9) + t9;
    r.e13 = (x.e13 + t10) + t10;
    r.e23 = (x.e23 + t11) + t11;
    return r;
}

/* exp of a Line: a unit Motor (closed form; non-finite input gives non-finite output). */
static inline pga3_Motorf pga3_line_expf(pga3_Linef x) {
    const float t0 = ((x.e12 * x.e12) + (x.e13 * x.e13)) + (x.e23 * x.e23);
    const pga3_Triplef t1 = pga3_exp_factorsf(t0);
    const float t2 = ((x.e01 * x.e23) - (x.e02 * x.e13)) + (x.e12 * x.e03);
    const float t3 = t2 * t1.y;
    pga3_Motorf r;
    r.scalar = t1.z;
    r.e01 = (t1.x * x.e01) + (t3 * x.e23);
    r.e02 = (t1.x * x.e02) - (t3 * x.e13);
    r.e12 = t1.x * x.e12;
    r.e03 = (t1.x * x.e03) + (t3 * x.e12);
    r.e13 = t1.x * x.e13;
    r.e23 = t1.x * x.e23;
    r.e0123 = t2 * t1.x;
    return r;
}

/* log of a unit Motor (m rev(m) = 1): the Line B with exp(B) = m, angle in [0, pi); a full turn gives non-finite output. */
static inline pga3_Linef pga3_motor_log_unitf(pga3_Motorf x) {
    const float t0 = sqrtf(((x.e12 * x.e12) + (x.e13 * x.e13)) + (x.e23 * x.e23));
    const pga3_Triplef t1 = pga3_log_factorsf(t0, x.scalar);
    const float t2 = x.e0123 * t1.y;
    pga3_Linef r;
    r.e01 = (t1.x * x.e01) - (t2 * x.e23);
    r.e02 = (t1.x * x.e02) + (t2 * x.e13);
    r.e12 = t1.x * x.e12;
    r.e03 = (t1.x * x.e03) - (t2 * x.e12);
    r.e13 = t1.x * x.e13;
    r.e23 = t1.x * x.e23;
    return r;
}

/* m / sqrt(m rev(m)) for a Motor: a unit Motor; a non-positive norm gives non-finite output. */
static inline pga3_Motorf pga3_motor_normalizef(pga3_Motorf x) {
    const float t0 = (x.scalar * x.scalar) - (((-(x.e12 * x.e12)) - (x.e13 * x.e13)) - (x.e23 * x.e23));
    const float t1 = 1.0f / t0;
    const float t2 = (x.scalar * x.e0123) - (((x.e01 * x.e23) - (x.e02 * x.e13)) + (x.e12 * x.e03));
    const float t3 = sqrtf(t1);
    const float t4 = (-(t2 * t3)) * t1;
    pga3_Motorf r;
    r.scalar = x.scalar * t3;
    r.e01 = (x.e01 * t3) + (-(t4 * x.e23));
    r.e02 = (x.e02 * t3) + (t4 * x.e13);
    r.e12 = x.e12 * t3;
    r.e03 = (x.e03 * t3) + (-(t4 * x.e12));
    r.e13 = x.e13 * t3;
    r.e23 = x.e23 * t3;
    r.e0123 = (x.e0123 * t3) + (x.scalar * t4);
    return r;
}

#endif /* GAM_PGA3_H */
