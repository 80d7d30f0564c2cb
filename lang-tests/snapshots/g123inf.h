/* g123inf: Motor=1,e12,e13,e23,e1inf,e2inf,e3inf,e123inf;Vector=grade1;Bivector=grade2; ops gp,sandwich,sandwich_unit,reverse,norm_squared,exp,log_unit,normalize */
#ifndef GAM_G123INF_H
#define GAM_G123INF_H

/* Motor: the coefficients of scalar, e12, e13, e23, e1inf, e2inf, e3inf, e123inf. */
typedef struct g123inf_Motor {
    double scalar;
    double e12;
    double e13;
    double e23;
    double e1inf;
    double e2inf;
    double e3inf;
    double e123inf;
} g123inf_Motor;

/* Vector: the coefficients of e1, e2, e3, einf. */
typedef struct g123inf_Vector {
    double e1;
    double e2;
    double e3;
    double einf;
} g123inf_Vector;

/* Bivector: the coefficients of e12, e13, e23, e1inf, e2inf, e3inf. */
typedef struct g123inf_Bivector {
    double e12;
    double e13;
    double e23;
    double e1inf;
    double e2inf;
    double e3inf;
} g123inf_Bivector;

/* The odd part of the algebra, declared automatically: some product of the declared types lands here. */
/* Odd: the coefficients of e1, e2, e3, einf, e123, e12inf, e13inf, e23inf. */
typedef struct g123inf_Odd {
    double e1;
    double e2;
    double e3;
    double einf;
    double e123;
    double e12inf;
    double e13inf;
    double e23inf;
} g123inf_Odd;

#include <math.h>

typedef struct g123inf_Triple {
    double x, y, z;
} g123inf_Triple;

/* (sinc t, (cos t - sinc t) / t^2, cos t) from t^2 >= 0 (series below t = 1e-3). */
static inline g123inf_Triple g123inf_exp_factors(double theta2) {
    const double theta = sqrt(theta2);
    if (theta < 0.001) {
        const double t4 = theta2 * theta2;
        { g123inf_Triple out; out.x = (1.0 - 0.16666666666666666 * theta2) + 0.008333333333333333 * t4; out.y = ((-0.3333333333333333) + 0.03333333333333333 * theta2) - 0.0011904761904761906 * t4; out.z = (1.0 - 0.5 * theta2) + 0.041666666666666664 * t4; return out; }
    } else {
        const double si = sin(theta);
        const double co = cos(theta);
        const double inv = 1.0 / theta;
        const double sinc = si * inv;
        { g123inf_Triple out; out.x = sinc; out.y = (co - sinc) * (inv * inv); out.z = co; return out; }
    }
}

/* (t / sin t, (t cos t - sin t) / sin^3 t, 0) from sin t >= 0 and cos t, t = atan2 (series below t = 1e-3). */
static inline g123inf_Triple g123inf_log_factors(double si, double co) {
    const double theta = atan2(si, co);
    if (theta < 0.001) {
        const double t2 = theta * theta;
        const double t4 = t2 * t2;
        { g123inf_Triple out; out.x = (1.0 + 0.16666666666666666 * t2) + 0.019444444444444445 * t4; out.y = ((-0.3333333333333333) - 0.13333333333333333 * t2) - 0.031746031746031744 * t4; out.z = 0.0; return out; }
    } else {
        const double r = 1.0 / si;
        const double r2 = r * r;
        { g123inf_Triple out; out.x = theta * r; out.y = (theta * co - si) * (r2 * r); out.z = 0.0; return out; }
    }
}

/* `gp` of a Motor and a Motor. */
static inline g123inf_Motor g123inf_motor_gp_motor(g123inf_Motor a, g123inf_Motor b) {
    const double t0 = a.scalar * b.scalar;
    const double t1 = a.scalar * b.e12;
    const double t2 = a.scalar * b.e13;
    const double t3 = a.scalar * b.e23;
    const double t4 = a.scalar * b.e1inf;
    const double t5 = a.scalar * b.e2inf;
    const double t6 = a.scalar * b.e3inf;
    const double t7 = a.scalar * b.e123inf;
    const double t8 = a.e12 * b.scalar;
    const double t9 = a.e12 * b.e12;
    const double t10 = a.e12 * b.e13;
    const double t11 = a.e12 * b.e23;
    const double t12 = a.e12 * b.e1inf;
    const double t13 = a.e12 * b.e2inf;
    const double t14 = a.e12 * b.e3inf;
    const double t15 = a.e12 * b.e123inf;
    const double t16 = a.e13 * b.scalar;
    const double t17 = a.e13 * b.e12;
    const double t18 = a.e13 * b.e13;
    const double t19 = a.e13 * b.e23;
    const double t20 = a.e13 * b.e1inf;
    const double t21 = a.e13 * b.e2inf;
    const double t22 = a.e13 * b.e3inf;
    const double t23 = a.e13 * b.e123inf;
    const double t24 = a.e23 * b.scalar;
    const double t25 = a.e23 * b.e12;
    const double t26 = a.e23 * b.e13;
    const double t27 = a.e23 * b.e23;
    const double t28 = a.e23 * b.e1inf;
    const double t29 = a.e23 * b.e2inf;
    const double t30 = a.e23 * b.e3inf;
    const double t31 = a.e23 * b.e123inf;
    const double t32 = a.e1inf * b.scalar;
    const double t33 = a.e1inf * b.e12;
    const double t34 = a.e1inf * b.e13;
    const double t35 = a.e1inf * b.e23;
    const double t36 = a.e2inf * b.scalar;
    const double t37 = a.e2inf * b.e12;
    const double t38 = a.e2inf * b.e13;
    const double t39 = a.e2inf * b.e23;
    const double t40 = a.e3inf * b.scalar;
    const double t41 = a.e3inf * b.e12;
    const double t42 = a.e3inf * b.e13;
    const double t43 = a.e3inf * b.e23;
    const double t44 = a.e123inf * b.scalar;
    const double t45 = a.e123inf * b.e12;
    const double t46 = a.e123inf * b.e13;
    const double t47 = a.e123inf * b.e23;
    g123inf_Motor r;
    r.scalar = ((t0 - t9) - t18) - t27;
    r.e12 = ((t1 + t8) + t26) - t19;
    r.e13 = ((t2 + t11) + t16) - t25;
    r.e23 = ((t3 + t17) + t24) - t10;
    r.e1inf = ((((((t4 + t13) + t22) - t31) + t32) - t37) - t42) - t47;
    r.e2inf = ((((((t5 + t23) + t30) - t12) + t33) + t36) + t46) - t43;
    r.e3inf = ((((((t6 - t15) - t20) - t29) + t34) + t39) + t40) - t45;
    r.e123inf = ((((((t7 + t14) + t28) - t21) + t35) + t41) + t44) - t38;
    return r;
}

/* `gp` of a Motor and a Vector. */
static inline g123inf_Odd g123inf_motor_gp_vector(g123inf_Motor a, g123inf_Vector b) {
    const double t0 = a.scalar * b.e1;
    const double t1 = a.scalar * b.e2;
    const double t2 = a.scalar * b.e3;
    const double t3 = a.scalar * b.einf;
    const double t4 = a.e12 * b.e1;
    const double t5 = a.e12 * b.e2;
    const double t6 = a.e12 * b.e3;
    const double t7 = a.e12 * b.einf;
    const double t8 = a.e13 * b.e1;
    const double t9 = a.e13 * b.e2;
    const double t10 = a.e13 * b.e3;
    const double t11 = a.e13 * b.einf;
    const double t12 = a.e23 * b.e1;
    const double t13 = a.e23 * b.e2;
    const double t14 = a.e23 * b.e3;
    const double t15 = a.e23 * b.einf;
    const double t16 = a.e1inf * b.e1;
    const double t17 = a.e1inf * b.e2;
    const double t18 = a.e1inf * b.e3;
    const double t19 = a.e2inf * b.e1;
    const double t20 = a.e2inf * b.e2;
    const double t21 = a.e2inf * b.e3;
    const double t22 = a.e3inf * b.e1;
    const double t23 = a.e3inf * b.e2;
    const double t24 = a.e3inf * b.e3;
    const double t25 = a.e123inf * b.e1;
    const double t26 = a.e123inf * b.e2;
    const double t27 = a.e123inf * b.e3;
    g123inf_Odd r;
    r.e1 = (t0 + t5) + t10;
    r.e2 = (t1 - t4) + t14;
    r.e3 = (t2 - t8) - t13;
    r.einf = ((t3 - t16) - t20) - t24;
    r.e123 = (t6 - t9) + t12;
    r.e12inf = ((t7 - t17) + t19) - t27;
    r.e13inf = ((t11 - t18) + t22) + t26;
    r.e23inf = ((t15 - t21) + t23) - t25;
    return r;
}

/* `gp` of a Motor and a Bivector. */
static inline g123inf_Motor g123inf_motor_gp_bivector(g123inf_Motor a, g123inf_Bivector b) {
    const double t0 = a.scalar * b.e12;
    const double t1 = a.scalar * b.e13;
    const double t2 = a.scalar * b.e23;
    const double t3 = a.scalar * b.e1inf;
    const double t4 = a.scalar * b.e2inf;
    const double t5 = a.scalar * b.e3inf;
    const double t6 = a.e12 * b.e12;
    const double t7 = a.e12 * b.e13;
    const double t8 = a.e12 * b.e23;
    const double t9 = a.e12 * b.e1inf;
    const double t10 = a.e12 * b.e2inf;
    const double t11 = a.e12 * b.e3inf;
    const double t12 = a.e13 * b.e12;
    const double t13 = a.e13 * b.e13;
    const double t14 = a.e13 * b.e23;
    const double t15 = a.e13 * b.e1inf;
    const double t16 = a.e13 * b.e2inf;
    const double t17 = a.e13 * b.e3inf;
    const double t18 = a.e23 * b.e12;
    const double t19 = a.e23 * b.e13;
    const double t20 = a.e23 * b.e23;
    const double t21 = a.e23 * b.e1inf;
    const double t22 = a.e23 * b.e2inf;
    const double t23 = a.e23 * b.e3inf;
    const double t24 = a.e1inf * b.e12;
    const double t25 = a.e1inf * b.e13;
    const double t26 = a.e1inf * b.e23;
    const double t27 = a.e2inf * b.e12;
    const double t28 = a.e2inf * b.e13;
    const double t29 = a.e2inf * b.e23;
    const double t30 = a.e3inf * b.e12;
    const double t31 = a.e3inf * b.e13;
    const double t32 = a.e3inf * b.e23;
    const double t33 = a.e123inf * b.e12;
    const double t34 = a.e123inf * b.e13;
    const double t35 = a.e123inf * b.e23;
    g123inf_Motor r;
    r.scalar = ((-t6) - t13) - t20;
    r.e12 = (t0 - t14) + t19;
    r.e13 = (t1 + t8) - t18;
    r.e23 = (t2 - t7) + t12;
    r.e1inf = (((t3 + t10) + t17) - t27) - (t31 + t35);
    r.e2inf = (((t4 - t9) + t23) + t24) - (t32 - t34);
    r.e3inf = (((t5 - t15) - t22) + t25) + (t29 - t33);
    r.e123inf = (((t11 - t16) + t21) + t26) - (t28 - t30);
    return r;
}

/* `gp` of a Vector and a Motor. */
static inline g123inf_Odd g123inf_vector_gp_motor(g123inf_Vector a, g123inf_Motor b) {
    const double t0 = a.e1 * b.scalar;
    const double t1 = a.e1 * b.e12;
    const double t2 = a.e1 * b.e13;
    const double t3 = a.e1 * b.e23;
    const double t4 = a.e1 * b.e1inf;
    const double t5 = a.e1 * b.e2inf;
    const double t6 = a.e1 * b.e3inf;
    const double t7 = a.e1 * b.e123inf;
    const double t8 = a.e2 * b.scalar;
    const double t9 = a.e2 * b.e12;
    const double t10 = a.e2 * b.e13;
    const double t11 = a.e2 * b.e23;
    const double t12 = a.e2 * b.e1inf;
    const double t13 = a.e2 * b.e2inf;
    const double t14 = a.e2 * b.e3inf;
    const double t15 = a.e2 * b.e123inf;
    const double t16 = a.e3 * b.scalar;
    const double t17 = a.e3 * b.e12;
    const double t18 = a.e3 * b.e13;
    const double t19 = a.e3 * b.e23;
    const double t20 = a.e3 * b.e1inf;
    const double t21 = a.e3 * b.e2inf;
    const double t22 = a.e3 * b.e3inf;
    const double t23 = a.e3 * b.e123inf;
    const double t24 = a.einf * b.scalar;
    const double t25 = a.einf * b.e12;
    const double t26 = a.einf * b.e13;
    const double t27 = a.einf * b.e23;
    g123inf_Odd r;
    r.e1 = (t0 - t9) - t18;
    r.e2 = (t1 + t8) - t19;
    r.e3 = (t2 + t11) + t16;
    r.einf = ((t4 + t13) + t22) + t24;
    r.e123 = (t3 - t10) + t17;
    r.e12inf = ((t5 - t12) + t23) + t25;
    r.e13inf = ((t6 - t15) - t20) + t26;
    r.e23inf = ((t7 + t14) - t21) + t27;
    return r;
}

/* `gp` of a Vector and a Vector. */
static inline g123inf_Motor g123inf_vector_gp_vector(g123inf_Vector a, g123inf_Vector b) {
    const double t0 = a.e1 * b.e1;
    const double t1 = a.e1 * b.e2;
    const double t2 = a.e1 * b.e3;
    const double t3 = a.e1 * b.einf;
    const double t4 = a.e2 * b.e1;
    const double t5 = a.e2 * b.e2;
    const double t6 = a.e2 * b.e3;
    const double t7 = a.e2 * b.einf;
    const double t8 = a.e3 * b.e1;
    const double t9 = a.e3 * b.e2;
    const double t10 = a.e3 * b.e3;
    const double t11 = a.e3 * b.einf;
    const double t12 = a.einf * b.e1;
    const double t13 = a.einf * b.e2;
    const double t14 = a.einf * b.e3;
    g123inf_Motor r;
    r.scalar = (t0 + t5) + t10;
    r.e12 = t1 - t4;
    r.e13 = t2 - t8;
    r.e23 = t6 - t9;
    r.e1inf = t3 - t12;
    r.e2inf = t7 - t13;
    r.e3inf = t11 - t14;
    r.e123inf = 0.0;
    return r;
}

/* `gp` of a Vector and a Bivector. */
static inline g123inf_Odd g123inf_vector_gp_bivector(g123inf_Vector a, g123inf_Bivector b) {
    const double t0 = a.e1 * b.e12;
    const double t1 = a.e1 * b.e13;
    const double t2 = a.e1 * b.e23;
    const double t3 = a.e1 * b.e1inf;
    const double t4 = a.e1 * b.e2inf;
    const double t5 = a.e1 * b.e3inf;
    const double t6 = a.e2 * b.e12;
    const double t7 = a.e2 * b.e13;
    const double t8 = a.e2 * b.e23;
    const double t9 = a.e2 * b.e1inf;
    const double t10 = a.e2 * b.e2inf;
    const double t11 = a.e2 * b.e3inf;
    const double t12 = a.e3 * b.e12;
    const double t13 = a.e3 * b.e13;
    const double t14 = a.e3 * b.e23;
    const double t15 = a.e3 * b.e1inf;
    const double t16 = a.e3 * b.e2inf;
    const double t17 = a.e3 * b.e3inf;
    const double t18 = a.einf * b.e12;
    const double t19 = a.einf * b.e13;
    const double t20 = a.einf * b.e23;
    g123inf_Odd r;
    r.e1 = (-t6) - t13;
    r.e2 = t0 - t14;
    r.e3 = t1 + t8;
    r.einf = (t3 + t10) + t17;
    r.e123 = (t2 - t7) + t12;
    r.e12inf = (t4 - t9) + t18;
    r.e13inf = (t5 - t15) + t19;
    r.e23inf = (t11 - t16) + t20;
    return r;
}

/* `gp` of a Bivector and a Motor. */
static inline g123inf_Motor g123inf_bivector_gp_motor(g123inf_Bivector a, g123inf_Motor b) {
    const double t0 = a.e12 * b.scalar;
    const double t1 = a.e12 * b.e12;
    const double t2 = a.e12 * b.e13;
    const double t3 = a.e12 * b.e23;
    const double t4 = a.e12 * b.e1inf;
    const double t5 = a.e12 * b.e2inf;
    const double t6 = a.e12 * b.e3inf;
    const double t7 = a.e12 * b.e123inf;
    const double t8 = a.e13 * b.scalar;
    const double t9 = a.e13 * b.e12;
    const double t10 = a.e13 * b.e13;
    const double t11 = a.e13 * b.e23;
    const double t12 = a.e13 * b.e1inf;
    const double t13 = a.e13 * b.e2inf;
    const double t14 = a.e13 * b.e3inf;
    const double t15 = a.e13 * b.e123inf;
    const double t16 = a.e23 * b.scalar;
    const double t17 = a.e23 * b.e12;
    const double t18 = a.e23 * b.e13;
    const double t19 = a.e23 * b.e23;
    const double t20 = a.e23 * b.e1inf;
    const double t21 = a.e23 * b.e2inf;
    const double t22 = a.e23 * b.e3inf;
    const double t23 = a.e23 * b.e123inf;
    const double t24 = a.e1inf * b.scalar;
    const double t25 = a.e1inf * b.e12;
    const double t26 = a.e1inf * b.e13;
    const double t27 = a.e1inf * b.e23;
    const double t28 = a.e2inf * b.scalar;
    const double t29 = a.e2inf * b.e12;
    const double t30 = a.e2inf * b.e13;
    const double t31 = a.e2inf * b.e23;
    const double t32 = a.e3inf * b.scalar;
    const double t33 = a.e3inf * b.e12;
    const double t34 = a.e3inf * b.e13;
    const double t35 = a.e3inf * b.e23;
    g123inf_Motor r;
    r.scalar = ((-t1) - t10) - t19;
    r.e12 = (t0 - t11) + t18;
    r.e13 = (t3 + t8) - t17;
    r.e23 = (t9 - t2) + t16;
    r.e1inf = (((t5 + t14) - t23) + t24) - (t29 + t34);
    r.e2inf = (((t15 - t4) + t22) + t25) + (t28 - t35);
    r.e3inf = (((t26 - t12) - t21) - t7) + (t31 + t32);
    r.e123inf = (((t6 - t13) + t20) + t27) - (t30 - t33);
    return r;
}

/* `gp` of a Bivector and a Vector. */
static inline g123inf_Odd g123inf_bivector_gp_vector(g123inf_Bivector a, g123inf_Vector b) {
    const double t0 = a.e12 * b.e1;
    const double t1 = a.e12 * b.e2;
    const double t2 = a.e12 * b.e3;
    const double t3 = a.e12 * b.einf;
    const double t4 = a.e13 * b.e1;
    const double t5 = a.e13 * b.e2;
    const double t6 = a.e13 * b.e3;
    const double t7 = a.e13 * b.einf;
    const double t8 = a.e23 * b.e1;
    const double t9 = a.e23 * b.e2;
    const double t10 = a.e23 * b.e3;
    const double t11 = a.e23 * b.einf;
    const double t12 = a.e1inf * b.e1;
    const double t13 = a.e1inf * b.e2;
    const double t14 = a.e1inf * b.e3;
    const double t15 = a.e2inf * b.e1;
    const double t16 = a.e2inf * b.e2;
    const double t17 = a.e2inf * b.e3;
    const double t18 = a.e3inf * b.e1;
    const double t19 = a.e3inf * b.e2;
    const double t20 = a.e3inf * b.e3;
    g123inf_Odd r;
    r.e1 = t1 + t6;
    r.e2 = t10 - t0;
    r.e3 = (-t4) - t9;
    r.einf = ((-t12) - t16) - t20;
    r.e123 = (t2 - t5) + t8;
    r.e12inf = (t3 - t13) + t15;
    r.e13inf = (t7 - t14) + t18;
    r.e23inf = (t11 - t17) + t19;
    return r;
}

/* `gp` of a Bivector and a Bivector. */
static inline g123inf_Motor g123inf_bivector_gp_bivector(g123inf_Bivector a, g123inf_Bivector b) {
    const double t0 = a.e12 * b.e12;
    const double t1 = a.e12 * b.e13;
    const double t2 = a.e12 * b.e23;
    const double t3 = a.e12 * b.e1inf;
    const double t4 = a.e12 * b.e2inf;
    const double t5 = a.e12 * b.e3inf;
    const double t6 = a.e13 * b.e12;
    const double t7 = a.e13 * b.e13;
    const double t8 = a.e13 * b.e23;
    const double t9 = a.e13 * b.e1inf;
    const double t10 = a.e13 * b.e2inf;
    const double t11 = a.e13 * b.e3inf;
    const double t12 = a.e23 * b.e12;
    const double t13 = a.e23 * b.e13;
    const double t14 = a.e23 * b.e23;
    const double t15 = a.e23 * b.e1inf;
    const double t16 = a.e23 * b.e2inf;
    const double t17 = a.e23 * b.e3inf;
    const double t18 = a.e1inf * b.e12;
    const double t19 = a.e1inf * b.e13;
    const double t20 = a.e1inf * b.e23;
    const double t21 = a.e2inf * b.e12;
    const double t22 = a.e2inf * b.e13;
    const double t23 = a.e2inf * b.e23;
    const double t24 = a.e3inf * b.e12;
    const double t25 = a.e3inf * b.e13;
    const double t26 = a.e3inf * b.e23;
    g123inf_Motor r;
    r.scalar = ((-t0) - t7) - t14;
    r.e12 = t13 - t8;
    r.e13 = t2 - t12;
    r.e23 = t6 - t1;
    r.e1inf = ((t4 + t11) - t21) - t25;
    r.e2inf = ((t17 - t3) + t18) - t26;
    r.e3inf = ((t19 - t16) - t9) + t23;
    r.e123inf = (((t5 - t10) + t15) + t20) - (t22 - t24);
    return r;
}

/* The reverse of a Motor. */
static inline g123inf_Motor g123inf_motor_reverse(g123inf_Motor x) {
    g123inf_Motor r;
    r.scalar = x.scalar;
    r.e12 = -x.e12;
    r.e13 = -x.e13;
    r.e23 = -x.e23;
    r.e1inf = -x.e1inf;
    r.e2inf = -x.e2inf;
    r.e3inf = -x.e3inf;
    r.e123inf = x.e123inf;
    return r;
}

/* The squared norm <x rev(x)>_0 of a Motor (may be negative or zero). */
static inline double g123inf_motor_norm_squared(g123inf_Motor x) {
    const double t0 = x.scalar * x.scalar;
    const double t1 = x.e12 * x.e12;
    const double t2 = x.e13 * x.e13;
    const double t3 = x.e23 * x.e23;
    return ((t0 + t1) + t2) + t3;
}

/* The reverse of a Vector. */
static inline g123inf_Vector g123inf_vector_reverse(g123inf_Vector x) {
    g123inf_Vector r;
    r.e1 = x.e1;
    r.e2 = x.e2;
    r.e3 = x.e3;
    r.einf = x.einf;
    return r;
}

/* The squared norm <x rev(x)>_0 of a Vector (may be negative or zero). */
static inline double g123inf_vector_norm_squared(g123inf_Vector x) {
    const double t0 = x.e1 * x.e1;
    const double t1 = x.e2 * x.e2;
    const double t2 = x.e3 * x.e3;
    return (t0 + t1) + t2;
}

/* The reverse of a Bivector. */
static inline g123inf_Bivector g123inf_bivector_reverse(g123inf_Bivector x) {
    g123inf_Bivector r;
    r.e12 = -x.e12;
    r.e13 = -x.e13;
    r.e23 = -x.e23;
    r.e1inf = -x.e1inf;
    r.e2inf = -x.e2inf;
    r.e3inf = -x.e3inf;
    return r;
}

/* The squared norm <x rev(x)>_0 of a Bivector (may be negative or zero). */
static inline double g123inf_bivector_norm_squared(g123inf_Bivector x) {
    const double t0 = x.e12 * x.e12;
    const double t1 = x.e13 * x.e13;
    const double t2 = x.e23 * x.e23;
    return (t0 + t1) + t2;
}

/* rev(S) x S for a Motor S and a Motor x, in one fused kernel. */
static inline g123inf_Motor g123inf_motor_sandwich_motor(g123inf_Motor s, g123inf_Motor x) {
    const double t0 = ((s.scalar * x.scalar) + (s.e12 * x.e12)) + ((s.e13 * x.e13) + (s.e23 * x.e23));
    const double t1 = ((s.scalar * x.e12) + (s.e13 * x.e23)) - ((s.e12 * x.scalar) + (s.e23 * x.e13));
    const double t2 = ((s.scalar * x.e13) + (s.e23 * x.e12)) - ((s.e12 * x.e23) + (s.e13 * x.scalar));
    const double t3 = ((s.scalar * x.e23) + (s.e12 * x.e13)) - ((s.e13 * x.e12) + (s.e23 * x.scalar));
    const double t4 = (((s.scalar * x.e1inf) + (s.e23 * x.e123inf)) + ((s.e2inf * x.e12) + (s.e3inf * x.e13))) - (((s.e12 * x.e2inf) + (s.e13 * x.e3inf)) + ((s.e1inf * x.scalar) + (s.e123inf * x.e23)));
    const double t5 = (((s.scalar * x.e2inf) + (s.e12 * x.e1inf)) + ((s.e3inf * x.e23) + (s.e123inf * x.e13))) - (((s.e13 * x.e123inf) + (s.e23 * x.e3inf)) + ((s.e1inf * x.e12) + (s.e2inf * x.scalar)));
    const double t6 = (((s.scalar * x.e3inf) + (s.e12 * x.e123inf)) + ((s.e13 * x.e1inf) + (s.e23 * x.e2inf))) - (((s.e1inf * x.e13) + (s.e2inf * x.e23)) + ((s.e3inf * x.scalar) + (s.e123inf * x.e12)));
    const double t7 = (((s.scalar * x.e123inf) + (s.e13 * x.e2inf)) + ((s.e2inf * x.e13) + (s.e123inf * x.scalar))) - (((s.e12 * x.e3inf) + (s.e23 * x.e1inf)) + ((s.e1inf * x.e23) + (s.e3inf * x.e12)));
    g123inf_Motor r;
    r.scalar = ((t0 * s.scalar) - (t1 * s.e12)) - ((t2 * s.e13) + (t3 * s.e23));
    r.e12 = ((t1 * s.scalar) + (t0 * s.e12)) + ((t3 * s.e13) - (t2 * s.e23));
    r.e13 = ((t2 * s.scalar) - (t3 * s.e12)) + ((t0 * s.e13) + (t1 * s.e23));
    r.e23 = ((t3 * s.scalar) + (t2 * s.e12)) - ((t1 * s.e13) - (t0 * s.e23));
    r.e1inf = (((t4 * s.scalar) - (t5 * s.e12)) - ((t6 * s.e13) + (t7 * s.e23))) + (((t0 * s.e1inf) + (t1 * s.e2inf)) + ((t2 * s.e3inf) - (t3 * s.e123inf)));
    r.e2inf = (((t5 * s.scalar) + (t4 * s.e12)) + ((t7 * s.e13) - (t6 * s.e23))) - (((t1 * s.e1inf) - (t0 * s.e2inf)) - ((t3 * s.e3inf) + (t2 * s.e123inf)));
    r.e3inf = (((t6 * s.scalar) - (t7 * s.e12)) + ((t4 * s.e13) + (t5 * s.e23))) - (((t2 * s.e1inf) + (t3 * s.e2inf)) - ((t0 * s.e3inf) - (t1 * s.e123inf)));
    r.e123inf = (((t7 * s.scalar) + (t6 * s.e12)) - ((t5 * s.e13) - (t4 * s.e23))) + (((t3 * s.e1inf) - (t2 * s.e2inf)) + ((t1 * s.e3inf) + (t0 * s.e123inf)));
    return r;
}

/* rev(S) x S for a Motor S and a Vector x, in one fused kernel. */
static inline g123inf_Vector g123inf_motor_sandwich_vector(g123inf_Motor s, g123inf_Vector x) {
    const double t0 = -((s.e12 * x.e2) + (s.e13 * x.e3));
    const double t1 = (s.e12 * x.e1) - (s.e23 * x.e3);
    const double t2 = (s.e13 * x.e1) + (s.e23 * x.e2);
    const double t3 = (s.e1inf * x.e1) + ((s.e2inf * x.e2) + (s.e3inf * x.e3));
    const double t4 = -(s.e123inf * x.e3);
    const double t5 = s.e123inf * x.e2;
    const double t6 = -(s.e123inf * x.e1);
    const double t7 = ((s.scalar * s.scalar) + (s.e12 * s.e12)) + ((s.e13 * s.e13) + (s.e23 * s.e23));
    const double t8 = (t0 * s.scalar) - ((t1 * s.e12) + (t2 * s.e13));
    const double t9 = (t1 * s.scalar) + ((t0 * s.e12) - (t2 * s.e23));
    const double t10 = (t2 * s.scalar) + ((t0 * s.e13) + (t1 * s.e23));
    const double t11 = ((t3 * s.scalar) - ((t4 * s.e12) + (t5 * s.e13))) - (((t6 * s.e23) - (t0 * s.e1inf)) - ((t1 * s.e2inf) + (t2 * s.e3inf)));
    g123inf_Vector r;
    r.e1 = (t7 * x.e1) + (t8 + t8);
    r.e2 = (t7 * x.e2) + (t9 + t9);
    r.e3 = (t7 * x.e3) + (t10 + t10);
    r.einf = (t7 * x.einf) + (t11 + t11);
    return r;
}

/* rev(S) x S for a Motor S and a Bivector x, in one fused kernel. */
static inline g123inf_Bivector g123inf_motor_sandwich_bivector(g123inf_Motor s, g123inf_Bivector x) {
    const double t0 = (s.e12 * x.e12) + ((s.e13 * x.e13) + (s.e23 * x.e23));
    const double t1 = (s.scalar * x.e12) + ((s.e13 * x.e23) - (s.e23 * x.e13));
    const double t2 = (s.scalar * x.e13) + ((s.e23 * x.e12) - (s.e12 * x.e23));
    const double t3 = (s.scalar * x.e23) + ((s.e12 * x.e13) - (s.e13 * x.e12));
    const double t4 = ((s.scalar * x.e1inf) + ((s.e2inf * x.e12) + (s.e3inf * x.e13))) - ((s.e12 * x.e2inf) + ((s.e13 * x.e3inf) + (s.e123inf * x.e23)));
    const double t5 = ((s.scalar * x.e2inf) + ((s.e12 * x.e1inf) + (s.e3inf * x.e23))) + ((s.e123inf * x.e13) - ((s.e23 * x.e3inf) + (s.e1inf * x.e12)));
    const double t6 = ((s.scalar * x.e3inf) + ((s.e13 * x.e1inf) + (s.e23 * x.e2inf))) - ((s.e1inf * x.e13) + ((s.e2inf * x.e23) + (s.e123inf * x.e12)));
    const double t7 = ((s.e13 * x.e2inf) + ((s.e2inf * x.e13) - (s.e12 * x.e3inf))) - ((s.e23 * x.e1inf) + ((s.e1inf * x.e23) + (s.e3inf * x.e12)));
    g123inf_Bivector r;
    r.e12 = ((t1 * s.scalar) + (t0 * s.e12)) + ((t3 * s.e13) - (t2 * s.e23));
    r.e13 = ((t2 * s.scalar) - (t3 * s.e12)) + ((t0 * s.e13) + (t1 * s.e23));
    r.e23 = ((t3 * s.scalar) + (t2 * s.e12)) - ((t1 * s.e13) - (t0 * s.e23));
    r.e1inf = (((t4 * s.scalar) - (t5 * s.e12)) - ((t6 * s.e13) + (t7 * s.e23))) + (((t0 * s.e1inf) + (t1 * s.e2inf)) + ((t2 * s.e3inf) - (t3 * s.e123inf)));
    r.e2inf = (((t5 * s.scalar) + (t4 * s.e12)) + ((t7 * s.e13) - (t6 * s.e23))) - (((t1 * s.e1inf) - (t0 * s.e2inf)) - ((t3 * s.e3inf) + (t2 * s.e123inf)));
    r.e3inf = (((t6 * s.scalar) - (t7 * s.e12)) + ((t4 * s.e13) + (t5 * s.e23))) - (((t2 * s.e1inf) + (t3 * s.e2inf)) - ((t0 * s.e3inf) - (t1 * s.e123inf)));
    return r;
}

/* rev(S) x S for a Vector S and a Motor x, in one fused kernel. */
static inline g123inf_Motor g123inf_vector_sandwich_motor(g123inf_Vector s, g123inf_Motor x) {
    const double t0 = (s.e1 * x.scalar) - ((s.e2 * x.e12) + (s.e3 * x.e13));
    const double t1 = (s.e1 * x.e12) + ((s.e2 * x.scalar) - (s.e3 * x.e23));
    const double t2 = (s.e1 * x.e13) + ((s.e2 * x.e23) + (s.e3 * x.scalar));
    const double t3 = (s.e1 * x.e23) + ((s.e3 * x.e12) - (s.e2 * x.e13));
    const double t4 = ((s.e1 * x.e1inf) + (s.e2 * x.e2inf)) + ((s.e3 * x.e3inf) + (s.einf * x.scalar));
    const double t5 = ((s.e1 * x.e2inf) + (s.e3 * x.e123inf)) + ((s.einf * x.e12) - (s.e2 * x.e1inf));
    const double t6 = ((s.e1 * x.e3inf) + (s.einf * x.e13)) - ((s.e2 * x.e123inf) + (s.e3 * x.e1inf));
    const double t7 = ((s.e1 * x.e123inf) + (s.e2 * x.e3inf)) + ((s.einf * x.e23) - (s.e3 * x.e2inf));
    g123inf_Motor r;
    r.scalar = (t0 * s.e1) + ((t1 * s.e2) + (t2 * s.e3));
    r.e12 = (t0 * s.e2) - ((t1 * s.e1) - (t3 * s.e3));
    r.e13 = (t0 * s.e3) - ((t2 * s.e1) + (t3 * s.e2));
    r.e23 = (t3 * s.e1) - ((t2 * s.e2) - (t1 * s.e3));
    r.e1inf = ((t0 * s.einf) - (t4 * s.e1)) - ((t5 * s.e2) + (t6 * s.e3));
    r.e2inf = ((t5 * s.e1) - (t4 * s.e2)) - ((t7 * s.e3) - (t1 * s.einf));
    r.e3inf = ((t6 * s.e1) + (t7 * s.e2)) - ((t4 * s.e3) - (t2 * s.einf));
    r.e123inf = ((t6 * s.e2) - (t7 * s.e1)) - ((t5 * s.e3) - (t3 * s.einf));
    return r;
}

/* rev(S) x S for a Vector S and a Vector x, in one fused kernel. */
static inline g123inf_Vector g123inf_vector_sandwich_vector(g123inf_Vector s, g123inf_Vector x) {
    const double t0 = (s.e1 * x.e1) + ((s.e2 * x.e2) + (s.e3 * x.e3));
    const double t1 = (s.e1 * x.e2) - (s.e2 * x.e1);
    const double t2 = (s.e1 * x.e3) - (s.e3 * x.e1);
    const double t3 = (s.e2 * x.e3) - (s.e3 * x.e2);
    const double t4 = (s.e1 * x.einf) - (s.einf * x.e1);
    const double t5 = (s.e2 * x.einf) - (s.einf * x.e2);
    const double t6 = (s.e3 * x.einf) - (s.einf * x.e3);
    g123inf_Vector r;
    r.e1 = (t0 * s.e1) + ((t1 * s.e2) + (t2 * s.e3));
    r.e2 = (t0 * s.e2) - ((t1 * s.e1) - (t3 * s.e3));
    r.e3 = (t0 * s.e3) - ((t2 * s.e1) + (t3 * s.e2));
    r.einf = ((t0 * s.einf) - (t4 * s.e1)) - ((t5 * s.e2) + (t6 * s.e3));
    return r;
}

/* rev(S) x S for a Vector S and a Bivector x, in one fused kernel. */
static inline g123inf_Bivector g123inf_vector_sandwich_bivector(g123inf_Vector s, g123inf_Bivector x) {
    const double t0 = -((s.e2 * x.e12) + (s.e3 * x.e13));
    const double t1 = (s.e1 * x.e12) - (s.e3 * x.e23);
    const double t2 = (s.e1 * x.e13) + (s.e2 * x.e23);
    const double t3 = (s.e1 * x.e1inf) + ((s.e2 * x.e2inf) + (s.e3 * x.e3inf));
    const double t4 = (s.e1 * s.e1) + ((s.e2 * s.e2) + (s.e3 * s.e3));
    const double t5 = (t0 * s.e2) - (t1 * s.e1);
    const double t6 = (t0 * s.e3) - (t2 * s.e1);
    const double t7 = (t1 * s.e3) - (t2 * s.e2);
    const double t8 = (t0 * s.einf) - (t3 * s.e1);
    const double t9 = (t1 * s.einf) - (t3 * s.e2);
    const double t10 = (t2 * s.einf) - (t3 * s.e3);
    g123inf_Bivector r;
    r.e12 = (t4 * x.e12) + (t5 + t5);
    r.e13 = (t4 * x.e13) + (t6 + t6);
    r.e23 = (t4 * x.e23) + (t7 + t7);
    r.e1inf = (t4 * x.e1inf) + (t8 + t8);
    r.e2inf = (t4 * x.e2inf) + (t9 + t9);
    r.e3inf = (t4 * x.e3inf) + (t10 + t10);
    return r;
}

/* rev(S) x S for a Bivector S and a Motor x, in one fused kernel. */
static inline g123inf_Motor g123inf_bivector_sandwich_motor(g123inf_Bivector s, g123inf_Motor x) {
    const double t0 = (s.e12 * x.e12) + ((s.e13 * x.e13) + (s.e23 * x.e23));
    const double t1 = (s.e13 * x.e23) - ((s.e12 * x.scalar) + (s.e23 * x.e13));
    const double t2 = (s.e23 * x.e12) - ((s.e12 * x.e23) + (s.e13 * x.scalar));
    const double t3 = (s.e12 * x.e13) - ((s.e13 * x.e12) + (s.e23 * x.scalar));
    const double t4 = ((s.e23 * x.e123inf) + ((s.e2inf * x.e12) + (s.e3inf * x.e13))) - ((s.e12 * x.e2inf) + ((s.e13 * x.e3inf) + (s.e1inf * x.scalar)));
    const double t5 = ((s.e12 * x.e1inf) + ((s.e3inf * x.e23) - (s.e13 * x.e123inf))) - ((s.e23 * x.e3inf) + ((s.e1inf * x.e12) + (s.e2inf * x.scalar)));
    const double t6 = ((s.e12 * x.e123inf) + ((s.e13 * x.e1inf) + (s.e23 * x.e2inf))) - ((s.e1inf * x.e13) + ((s.e2inf * x.e23) + (s.e3inf * x.scalar)));
    const double t7 = ((s.e13 * x.e2inf) + ((s.e2inf * x.e13) - (s.e12 * x.e3inf))) - ((s.e23 * x.e1inf) + ((s.e1inf * x.e23) + (s.e3inf * x.e12)));
    g123inf_Motor r;
    r.scalar = -((t1 * s.e12) + ((t2 * s.e13) + (t3 * s.e23)));
    r.e12 = (t0 * s.e12) + ((t3 * s.e13) - (t2 * s.e23));
    r.e13 = (t0 * s.e13) - ((t3 * s.e12) - (t1 * s.e23));
    r.e23 = (t2 * s.e12) - ((t1 * s.e13) - (t0 * s.e23));
    r.e1inf = ((t0 * s.e1inf) - ((t5 * s.e12) + (t6 * s.e13))) - ((t7 * s.e23) - ((t1 * s.e2inf) + (t2 * s.e3inf)));
    r.e2inf = ((t4 * s.e12) + ((t7 * s.e13) - (t6 * s.e23))) - ((t1 * s.e1inf) - ((t0 * s.e2inf) + (t3 * s.e3inf)));
    r.e3inf = ((t4 * s.e13) - ((t7 * s.e12) - (t5 * s.e23))) - ((t2 * s.e1inf) + ((t3 * s.e2inf) - (t0 * s.e3inf)));
    r.e123inf = ((t6 * s.e12) - ((t5 * s.e13) - (t4 * s.e23))) + ((t3 * s.e1inf) - ((t2 * s.e2inf) - (t1 * s.e3inf)));
    return r;
}

/* rev(S) x S for a Bivector S and a Vector x, in one fused kernel. */
static inline g123inf_Vector g123inf_bivector_sandwich_vector(g123inf_Bivector s, g123inf_Vector x) {
    const double t0 = -((s.e12 * x.e2) + (s.e13 * x.e3));
    const double t1 = (s.e12 * x.e1) - (s.e23 * x.e3);
    const double t2 = (s.e13 * x.e1) + (s.e23 * x.e2);
    const double t3 = (s.e12 * s.e12) + ((s.e13 * s.e13) + (s.e23 * s.e23));
    const double t4 = -((t1 * s.e12) + (t2 * s.e13));
    const double t5 = (t0 * s.e12) - (t2 * s.e23);
    const double t6 = (t0 * s.e13) + (t1 * s.e23);
    const double t7 = (t0 * s.e1inf) + ((t1 * s.e2inf) + (t2 * s.e3inf));
    g123inf_Vector r;
    r.e1 = (t3 * x.e1) + (t4 + t4);
    r.e2 = (t3 * x.e2) + (t5 + t5);
    r.e3 = (t3 * x.e3) + (t6 + t6);
    r.einf = (t3 * x.einf) + (t7 + t7);
    return r;
}

/* rev(S) x S for a Bivector S and a Bivector x, in one fused kernel. */
static inline g123inf_Bivector g123inf_bivector_sandwich_bivector(g123inf_Bivector s, g123inf_Bivector x) {
    const double t0 = (s.e12 * x.e12) + ((s.e13 * x.e13) + (s.e23 * x.e23));
    const double t1 = (s.e13 * x.e23) - (s.e23 * x.e13);
    const double t2 = (s.e23 * x.e12) - (s.e12 * x.e23);
    const double t3 = (s.e12 * x.e13) - (s.e13 * x.e12);
    const double t4 = ((s.e2inf * x.e12) + (s.e3inf * x.e13)) - ((s.e12 * x.e2inf) + (s.e13 * x.e3inf));
    const double t5 = ((s.e12 * x.e1inf) + (s.e3inf * x.e23)) - ((s.e23 * x.e3inf) + (s.e1inf * x.e12));
    const double t6 = ((s.e13 * x.e1inf) + (s.e23 * x.e2inf)) - ((s.e1inf * x.e13) + (s.e2inf * x.e23));
    const double t7 = ((s.e13 * x.e2inf) + ((s.e2inf * x.e13) - (s.e12 * x.e3inf))) - ((s.e23 * x.e1inf) + ((s.e1inf * x.e23) + (s.e3inf * x.e12)));
    g123inf_Bivector r;
    r.e12 = (t0 * s.e12) + ((t3 * s.e13) - (t2 * s.e23));
    r.e13 = (t0 * s.e13) - ((t3 * s.e12) - (t1 * s.e23));
    r.e23 = (t2 * s.e12) - ((t1 * s.e13) - (t0 * s.e23));
    r.e1inf = ((t0 * s.e1inf) - ((t5 * s.e12) + (t6 * s.e13))) - ((t7 * s.e23) - ((t1 * s.e2inf) + (t2 * s.e3inf)));
    r.e2inf = ((t4 * s.e12) + ((t7 * s.e13) - (t6 * s.e23))) - ((t1 * s.e1inf) - ((t0 * s.e2inf) + (t3 * s.e3inf)));
    r.e3inf = ((t4 * s.e13) - ((t7 * s.e12) - (t5 * s.e23))) - ((t2 * s.e1inf) + ((t3 * s.e2inf) - (t0 * s.e3inf)));
    return r;
}

/* rev(S) x S for a unit Motor S (S rev(S) = 1) and a Motor x; not the action otherwise. */
static inline g123inf_Motor g123inf_motor_sandwich_unit_motor(g123inf_Motor s, g123inf_Motor x) {
    const double t0 = (s.e13 * x.e23) - (s.e23 * x.e13);
    const double t1 = -((s.e12 * x.e23) - (s.e23 * x.e12));
    const double t2 = (s.e12 * x.e13) - (s.e13 * x.e12);
    const double t3 = -(((s.e12 * x.e2inf) + (s.e13 * x.e3inf)) - ((s.e2inf * x.e12) + (s.e3inf * x.e13)));
    const double t4 = ((s.e12 * x.e1inf) - (s.e23 * x.e3inf)) - ((s.e1inf * x.e12) - (s.e3inf * x.e23));
    const double t5 = ((s.e13 * x.e1inf) + (s.e23 * x.e2inf)) - ((s.e1inf * x.e13) + (s.e2inf * x.e23));
    const double t6 = (t0 * s.scalar) - ((t1 * s.e23) - (t2 * s.e13));
    const double t7 = (t0 * s.e23) + ((t1 * s.scalar) - (t2 * s.e12));
    const double t8 = -((t0 * s.e13) - ((t1 * s.e12) + (t2 * s.scalar)));
    const double t9 = ((t0 * s.e2inf) + ((t1 * s.e3inf) - (t2 * s.e123inf))) + ((t3 * s.scalar) - ((t4 * s.e12) + (t5 * s.e13)));
    const double t10 = -(((t0 * s.e1inf) - ((t1 * s.e123inf) + (t2 * s.e3inf))) - ((t3 * s.e12) + ((t4 * s.scalar) - (t5 * s.e23))));
    const double t11 = -(((t0 * s.e123inf) + ((t1 * s.e1inf) + (t2 * s.e2inf))) - ((t3 * s.e13) + ((t4 * s.e23) + (t5 * s.scalar))));
    g123inf_Motor r;
    r.scalar = x.scalar;
    r.e12 = (x.e12 + t6) + t6;
    r.e13 = (x.e13 + t7) + t7;
    r.e23 = (x.e23 + t8) + t8;
    r.e1inf = (x.e1inf + t9) + t9;
    r.e2inf = (x.e2inf + t10) + t10;
    r.e3inf = (x.e3inf + t11) + t11;
    r.e123inf = x.e123inf;
    return r;
}

/* rev(S) x S for a unit Motor S (S rev(S) = 1) and a Vector x; not the action otherwise. */
static inline g123inf_Vector g123inf_motor_sandwich_unit_vector(g123inf_Motor s, g123inf_Vector x) {
    const double t0 = -((s.e12 * x.e2) + (s.e13 * x.e3));
    const double t1 = (s.e12 * x.e1) - (s.e23 * x.e3);
    const double t2 = (s.e13 * x.e1) + (s.e23 * x.e2);
    const double t3 = (s.e1inf * x.e1) + ((s.e2inf * x.e2) + (s.e3inf * x.e3));
    const double t4 = -(s.e123inf * x.e3);
    const double t5 = s.e123inf * x.e2;
    const double t6 = -(s.e123inf * x.e1);
    const double t7 = (t0 * s.scalar) - ((t1 * s.e12) + (t2 * s.e13));
    const double t8 = (t0 * s.e12) + ((t1 * s.scalar) - (t2 * s.e23));
    const double t9 = (t0 * s.e13) + ((t1 * s.e23) + (t2 * s.scalar));
    const double t10 = ((t0 * s.e1inf) + ((t1 * s.e2inf) + (t2 * s.e3inf))) + (((t3 * s.scalar) - (t4 * s.e12)) - ((t5 * s.e13) + (t6 * s.e23)));
    g123inf_Vector r;
    r.e1 = (x.e1 + t7) + t7;
    r.e2 = (x.e2 + t8) + t8;
    r.e3 = (x.e3 + t9) + t9;
    r.einf = (x.einf + t10) + t10;
    return r;
}

/* rev(S) x S for a unit Motor S (S rev(S) = 1) and a Bivector x; not the action otherwise. */
static inline g123inf_Bivector g123inf_motor_sandwich_unit_bivector(g123inf_Motor s, g123inf_Bivector x) {
    const double t0 = (s.e13 * x.e23) - (s.e23 * x.e13);
    const double t1 = -((s.e12 * x.e23) - (s.e23 * x.e12));
    const double t2 = (s.e12 * x.e13) - (s.e13 * x.e12);
    const double t3 = -(((s.e12 * x.e2inf) + (s.e13 * x.e3inf)) - ((s.e2inf * x.e12) + (s.e3inf * x.e13)));
    const double t4 = ((s.e12 * x.e1inf) - (s.e23 * x.e3inf)) - ((s.e1inf * x.e12) - (s.e3inf * x.e23));
    const double t5 = ((s.e13 * x.e1inf) + (s.e23 * x.e2inf)) - ((s.e1inf * x.e13) + (s.e2inf * x.e23));
    const double t6 = (t0 * s.scalar) - ((t1 * s.e23) - (t2 * s.e13));
    const double t7 = (t0 * s.e23) + ((t1 * s.scalar) - (t2 * s.e12));
    const double t8 = -((t0 * s.e13) - ((t1 * s.e12) + (t2 * s.scalar)));
    const double t9 = ((t0 * s.e2inf) + ((t1 * s.e3inf) - (t2 * s.e123inf))) + ((t3 * s.scalar) - ((t4 * s.e12) + (t5 * s.e13)));
    const double t10 = -(((t0 * s.e1inf) - ((t1 * s.e123inf) + (t2 * s.e3inf))) - ((t3 * s.e12) + ((t4 * s.scalar) - (t5 * s.e23))));
    const double t11 = -(((t0 * s.e123inf) + ((t1 * s.e1inf) + (t2 * s.e2inf))) - ((t3 * s.e13) + ((t4 * s.e23) + (t5 * s.scalar))));
    g123inf_Bivector r;
    r.e12 = (x.e12 + t6) + t6;
    r.e13 = (x.e13 + t7) + t7;
    r.e23 = (x.e23 + t8) + t8;
    r.e1inf = (x.e1inf + t9) + t9;
    r.e2inf = (x.e2inf + t10) + t10;
    r.e3inf = (x.e3inf + t11) + t11;
    return r;
}

/* rev(S) x S for a unit Vector S (S rev(S) = 1) and a Motor x; not the action otherwise. */
static inline g123inf_Motor g123inf_vector_sandwich_unit_motor(g123inf_Vector s, g123inf_Motor x) {
    const double t0 = -((s.e2 * x.e12) + (s.e3 * x.e13));
    const double t1 = (s.e1 * x.e12) - (s.e3 * x.e23);
    const double t2 = (s.e1 * x.e13) + (s.e2 * x.e23);
    const double t3 = (s.e1 * x.e1inf) + ((s.e2 * x.e2inf) + (s.e3 * x.e3inf));
    const double t4 = s.e3 * x.e123inf;
    const double t5 = -(s.e2 * x.e123inf);
    const double t6 = s.e1 * x.e123inf;
    const double t7 = (t0 * s.e2) - (t1 * s.e1);
    const double t8 = (t0 * s.e3) - (t2 * s.e1);
    const double t9 = (t1 * s.e3) - (t2 * s.e2);
    const double t10 = ((t0 * s.einf) - (t3 * s.e1)) - ((t4 * s.e2) + (t5 * s.e3));
    const double t11 = ((t1 * s.einf) - (t3 * s.e2)) + ((t4 * s.e1) - (t6 * s.e3));
    const double t12 = ((t2 * s.einf) - (t3 * s.e3)) + ((t5 * s.e1) + (t6 * s.e2));
    const double t13 = -((t4 * s.e3) - ((t5 * s.e2) - (t6 * s.e1)));
    g123inf_Motor r;
    r.scalar = x.scalar;
    r.e12 = (x.e12 + t7) + t7;
    r.e13 = (x.e13 + t8) + t8;
    r.e23 = (x.e23 + t9) + t9;
    r.e1inf = (x.e1inf + t10) + t10;
    r.e2inf = (x.e2inf + t11) + t11;
    r.e3inf = (x.e3inf + t12) + t12;
    r.e123inf = (x.e123inf + t13) + t13;
    return r;
}

/* rev(S) x S for a unit Vector S (S rev(S) = 1) and a Vector x; not the action otherwise. */
static inline g123inf_Vector g123inf_vector_sandwich_unit_vector(g123inf_Vector s, g123inf_Vector x) {
    const double t0 = (s.e1 * x.e2) - (s.e2 * x.e1);
    const double t1 = (s.e1 * x.e3) - (s.e3 * x.e1);
    const double t2 = (s.e2 * x.e3) - (s.e3 * x.e2);
    const double t3 = (s.e1 * x.einf) - (s.einf * x.e1);
    const double t4 = (s.e2 * x.einf) - (s.einf * x.e2);
    const double t5 = (s.e3 * x.einf) - (s.einf * x.e3);
    const double t6 = (t0 * s.e2) + (t1 * s.e3);
    const double t7 = -((t0 * s.e1) - (t2 * s.e3));
    const double t8 = -((t1 * s.e1) + (t2 * s.e2));
    const double t9 = -((t3 * s.e1) + ((t4 * s.e2) + (t5 * s.e3)));
    g123inf_Vector r;
    r.e1 = (x.e1 + t6) + t6;
    r.e2 = (x.e2 + t7) + t7;
    r.e3 = (x.e3 + t8) + t8;
    r.einf = (x.einf + t9) + t9;
    return r;
}

/* rev(S) x S for a unit Vector S (S rev(S) = 1) and a Bivector x; not the action otherwise. */
static inline g123inf_Bivector g123inf_vector_sandwich_unit_bivector(g123inf_Vector s, g123inf_Bivector x) {
    const double t0 = -((s.e2 * x.e12) + (s.e3 * x.e13));
    const double t1 = (s.e1 * x.e12) - (s.e3 * x.e23);
    const double t2 = (s.e1 * x.e13) + (s.e2 * x.e23);
    const double t3 = (s.e1 * x.e1inf) + ((s.e2 * x.e2inf) + (s.e3 * x.e3inf));
    const double t4 = (t0 * s.e2) - (t1 * s.e1);
    const double t5 = (t0 * s.e3) - (t2 * s.e1);
    const double t6 = (t1 * s.e3) - (t2 * s.e2);
    const double t7 = (t0 * s.einf) - (t3 * s.e1);
    const double t8 = (t1 * s.einf) - (t3 * s.e2);
    const double t9 = (t2 * s.einf) - (t3 * s.e3);
    g123inf_Bivector r;
    r.e12 = (x.e12 + t4) + t4;
    r.e13 = (x.e13 + t5) + t5;
    r.e23 = (x.e23 + t6) + t6;
    r.e1inf = (x.e1inf + t7) + t7;
    r.e2inf = (x.e2inf + t8) + t8;
    r.e3inf = (x.e3inf + t9) + t9;
    return r;
}

/* rev(S) x S for a unit Bivector S (S rev(S) = 1) and a Motor x; not the action otherwise. */
static inline g123inf_Motor g123inf_bivector_sandwich_unit_motor(g123inf_Bivector s, g123inf_Motor x) {
    const double t0 = (s.e13 * x.e23) - (s.e23 * x.e13);
    const double t1 = -((s.e12 * x.e23) - (s.e23 * x.e12));
    const double t2 = (s.e12 * x.e13) - (s.e13 * x.e12);
    const double t3 = -(((s.e12 * x.e2inf) + (s.e13 * x.e3inf)) - ((s.e2inf * x.e12) + (s.e3inf * x.e13)));
    const double t4 = ((s.e12 * x.e1inf) - (s.e23 * x.e3inf)) - ((s.e1inf * x.e12) - (s.e3inf * x.e23));
    const double t5 = ((s.e13 * x.e1inf) + (s.e23 * x.e2inf)) - ((s.e1inf * x.e13) + (s.e2inf * x.e23));
    const double t6 = -((t1 * s.e23) - (t2 * s.e13));
    const double t7 = (t0 * s.e23) - (t2 * s.e12);
    const double t8 = -((t0 * s.e13) - (t1 * s.e12));
    const double t9 = ((t0 * s.e2inf) + (t1 * s.e3inf)) - ((t4 * s.e12) + (t5 * s.e13));
    const double t10 = -(((t0 * s.e1inf) - (t2 * s.e3inf)) - ((t3 * s.e12) - (t5 * s.e23)));
    const double t11 = -(((t1 * s.e1inf) + (t2 * s.e2inf)) - ((t3 * s.e13) + (t4 * s.e23)));
    g123inf_Motor r;
    r.scalar = x.scalar;
    r.e12 = (x.e12 + t6) + t6;
    r.e13 = (x.e13 + t7) + t7;
    r.e23 = (x.e23 + t8) + t8;
    r.e1inf = (x.e1inf + t9) + t9;
    r.e2inf = (x.e2inf + t10) + t10;
    r.e3inf = (x.e3inf + t11) + t11;
    r.e123inf = x.e123inf;
    return r;
}

/* rev(S) x S for a unit Bivector S (S rev(S) = 1) and a Vector x; not the action otherwise. */
static inline g123inf_Vector g123inf_bivector_sandwich_unit_vector(g123inf_Bivector s, g123inf_Vector x) {
    const double t0 = -((s.e12 * x.e2) + (s.e13 * x.e3));
    const double t1 = (s.e12 * x.e1) - (s.e23 * x.e3);
    const double t2 = (s.e13 * x.e1) + (s.e23 * x.e2);
    const double t3 = -((t1 * s.e12) + (t2 * s.e13));
    const double t4 = (t0 * s.e12) - (t2 * s.e23);
    const double t5 = (t0 * s.e13) + (t1 * s.e23);
    const double t6 = (t0 * s.e1inf) + ((t1 * s.e2inf) + (t2 * s.e3inf));
    g123inf_Vector r;
    r.e1 = (x.e1 + t3) + t3;
    r.e2 = (x.e2 + t4) + t4;
    r.e3 = (x.e3 + t5) + t5;
    r.einf = (x.einf + t6) + t6;
    return r;
}

/* rev(S) x S for a unit Bivector S (S rev(S) = 1) and a Bivector x; not the action otherwise. */
static inline g123inf_Bivector g123inf_bivector_sandwich_unit_bivector(g123inf_Bivector s, g123inf_Bivector x) {
    const double t0 = (s.e13 * x.e23) - (s.e23 * x.e13);
    const double t1 = -((s.e12 * x.e23) - (s.e23 * x.e12));
    const double t2 = (s.e12 * x.e13) - (s.e13 * x.e12);
    const double t3 = -(((s.e12 * x.e2inf) + (s.e13 * x.e3inf)) - ((s.e2inf * x.e12) + (s.e3inf * x.e13)));
    const double t4 = ((s.e12 * x.e1inf) - (s.e23 * x.e3inf)) - ((s.e1inf * x.e12) - (s.e3inf * x.e23));
    const double t5 = ((s.e13 * x.e1inf) + (s.e23 * x.e2inf)) - ((s.e1inf * x.e13) + (s.e2inf * x.e23));
    const double t6 = -((t1 * s.e23) - (t2 * s.e13));
    const double t7 = (t0 * s.e23) - (t2 * s.e12);
    const double t8 = -((t0 * s.e13) - (t1 * s.e12));
    const double t9 = ((t0 * s.e2inf) + (t1 * s.e3inf)) - ((t4 * s.e12) + (t5 * s.e13));
    const double t10 = -(((t0 * s.e1inf) - (t2 * s.e3inf)) - ((t3 * s.e12) - (t5 * s.e23)));
    const double t11 = -(((t1 * s.e1inf) + (t2 * s.e2inf)) - ((t3 * s.e13) + (t4 * s.e23)));
    g123inf_Bivector r;
    r.e12 = (x.e12 + t6) + t6;
    r.e13 = (x.e13 + t7) + t7;
    r.e23 = (x.e23 + t8) + t8;
    r.e1inf = (x.e1inf + t9) + t9;
    r.e2inf = (x.e2inf + t10) + t10;
    r.e3inf = (x.e3inf + t11) + t11;
    return r;
}

/* exp of a Bivector: a unit Motor (closed form; non-finite input gives non-finite output). */
static inline g123inf_Motor g123inf_bivector_exp(g123inf_Bivector x) {
    const double t0 = ((x.e12 * x.e12) + (x.e13 * x.e13)) + (x.e23 * x.e23);
    const g123inf_Triple t1 = g123inf_exp_factors(t0);
    const double t2 = ((x.e12 * x.e3inf) - (x.e13 * x.e2inf)) + (x.e23 * x.e1inf);
    const double t3 = t2 * t1.y;
    g123inf_Motor r;
    r.scalar = t1.z;
    r.e12 = t1.x * x.e12;
    r.e13 = t1.x * x.e13;
    r.e23 = t1.x * x.e23;
    r.e1inf = (t1.x * x.e1inf) + (t3 * x.e23);
    r.e2inf = (t1.x * x.e2inf) - (t3 * x.e13);
    r.e3inf = (t1.x * x.e3inf) + (t3 * x.e12);
    r.e123inf = t2 * t1.x;
    return r;
}

/* log of a unit Motor (m rev(m) = 1): the Bivector B with exp(B) = m, angle in [0, pi); a full turn gives non-finite output. */
static inline g123inf_Bivector g123inf_motor_log_unit(g123inf_Motor x) {
    const double t0 = sqrt(((x.e12 * x.e12) + (x.e13 * x.e13)) + (x.e23 * x.e23));
    const g123inf_Triple t1 = g123inf_log_factors(t0, x.scalar);
    const double t2 = x.e123inf * t1.y;
    g123inf_Bivector r;
    r.e12 = t1.x * x.e12;
    r.e13 = t1.x * x.e13;
    r.e23 = t1.x * x.e23;
    r.e1inf = (t1.x * x.e1inf) - (t2 * x.e23);
    r.e2inf = (t1.x * x.e2inf) + (t2 * x.e13);
    r.e3inf = (t1.x * x.e3inf) - (t2 * x.e12);
    return r;
}

/* m / sqrt(m rev(m)) for a Motor: a unit Motor; a non-positive norm gives non-finite output. */
static inline g123inf_Motor g123inf_motor_normalize(g123inf_Motor x) {
    const double t0 = (x.scalar * x.scalar) - (((-(x.e12 * x.e12)) - (x.e13 * x.e13)) - (x.e23 * x.e23));
    const double t1 = 1.0 / t0;
    const double t2 = (x.scalar * x.e123inf) - (((x.e12 * x.e3inf) - (x.e13 * x.e2inf)) + (x.e23 * x.e1inf));
    const double t3 = sqrt(t1);
    const double t4 = (-(t2 * t3)) * t1;
    g123inf_Motor r;
    r.scalar = x.scalar * t3;
    r.e12 = x.e12 * t3;
    r.e13 = x.e13 * t3;
    r.e23 = x.e23 * t3;
    r.e1inf = (x.e1inf * t3) + (-(t4 * x.e23));
    r.e2inf = (x.e2inf * t3) + (t4 * x.e13);
    r.e3inf = (x.e3inf * t3) + (-(t4 * x.e12));
    r.e123inf = (x.e123inf * t3) + (x.scalar * t4);
    return r;
}

/* Motor: the coefficients of scalar, e12, e13, e23, e1inf, e2inf, e3inf, e123inf. */
typedef struct g123inf_Motorf {
    float scalar;
    float e12;
    float e13;
    float e23;
    float e1inf;
    float e2inf;
    float e3inf;
    float e123inf;
} g123inf_Motorf;

/* Vector: the coefficients of e1, e2, e3, einf. */
typedef struct g123inf_Vectorf {
    float e1;
    float e2;
    float e3;
    float einf;
} g123inf_Vectorf;

/* Bivector: the coefficients of e12, e13, e23, e1inf, e2inf, e3inf. */
typedef struct g123inf_Bivectorf {
    float e12;
    float e13;
    float e23;
    float e1inf;
    float e2inf;
    float e3inf;
} g123inf_Bivectorf;

/* The odd part of the algebra, declared automatically: some product of the declared types lands here. */
/* Odd: the coefficients of e1, e2, e3, einf, e123, e12inf, e13inf, e23inf. */
typedef struct g123inf_Oddf {
    float e1;
    float e2;
    float e3;
    float einf;
    float e123;
    float e12inf;
    float e13inf;
    float e23inf;
} g123inf_Oddf;

#include <math.h>

typedef struct g123inf_Triplef {
    float x, y, z;
} g123inf_Triplef;

/* (sinc t, (cos t - sinc t) / t^2, cos t) from t^2 >= 0 (series below t = 1e-3). */
static inline g123inf_Triplef g123inf_exp_factorsf(float theta2) {
    const float theta = sqrtf(theta2);
    if (theta < 0.001f) {
        const float t4 = theta2 * theta2;
        { g123inf_Triplef out; out.x = (1.0f - 0.16666667f * theta2) + 0.008333334f * t4; out.y = ((-0.33333334f) + 0.033333335f * theta2) - 0.0011904762f * t4; out.z = (1.0f - 0.5f * theta2) + 0.041666668f * t4; return out; }
    } else {
        const float si = sinf(theta);
        const float co = cosf(theta);
        const float inv = 1.0f / theta;
        const float sinc = si * inv;
        { g123inf_Triplef out; out.x = sinc; out.y = (co - sinc) * (inv * inv); out.z = co; return out; }
    }
}

/* (t / sin t, (t cos t - sin t) / sin^3 t, 0) from sin t >= 0 and cos t, t = atan2 (series below t = 1e-3). */
static inline g123inf_Triplef g123inf_log_factorsf(float si, float co) {
    const float theta = atan2f(si, co);
    if (theta < 0.001f) {
        const float t2 = theta * theta;
        const float t4 = t2 * t2;
        { g123inf_Triplef out; out.x = (1.0f + 0.16666667f * t2) + 0.019444445f * t4; out.y = ((-0.33333334f) - 0.13333334f * t2) - 0.031746034f * t4; out.z = 0.0f; return out; }
    } else {
        const float r = 1.0f / si;
        const float r2 = r * r;
        { g123inf_Triplef out; out.x = theta * r; out.y = (theta * co - si) * (r2 * r); out.z = 0.0f; return out; }
    }
}

/* `gp` of a Motor and a Motor. */
static inline g123inf_Motorf g123inf_motor_gp_motorf(g123inf_Motorf a, g123inf_Motorf b) {
    const float t0 = a.scalar * b.scalar;
    const float t1 = a.scalar * b.e12;
    const float t2 = a.scalar * b.e13;
    const float t3 = a.scalar * b.e23;
    const float t4 = a.scalar * b.e1inf;
    const float t5 = a.scalar * b.e2inf;
    const float t6 = a.scalar * b.e3inf;
    const float t7 = a.scalar * b.e123inf;
    const float t8 = a.e12 * b.scalar;
    const float t9 = a.e12 * b.e12;
    const float t10 = a.e12 * b.e13;
    const float t11 = a.e12 * b.e23;
    const float t12 = a.e12 * b.e1inf;
    const float t13 = a.e12 * b.e2inf;
    const float t14 = a.e12 * b.e3inf;
    const float t15 = a.e12 * b.e123inf;
    const float t16 = a.e13 * b.scalar;
    const float t17 = a.e13 * b.e12;
    const float t18 = a.e13 * b.e13;
    const float t19 = a.e13 * b.e23;
    const float t20 = a.e13 * b.e1inf;
    const float t21 = a.e13 * b.e2inf;
    const float t22 = a.e13 * b.e3inf;
    const float t23 = a.e13 * b.e123inf;
    const float t24 = a.e23 * b.scalar;
    const float t25 = a.e23 * b.e12;
    const float t26 = a.e23 * b.e13;
    const float t27 = a.e23 * b.e23;
    const float t28 = a.e23 * b.e1inf;
    const float t29 = a.e23 * b.e2inf;
    const float t30 = a.e23 * b.e3inf;
    const float t31 = a.e23 * b.e123inf;
    const float t32 = a.e1inf * b.scalar;
    const float t33 = a.e1inf * b.e12;
    const float t34 = a.e1inf * b.e13;
    const float t35 = a.e1inf * b.e23;
    const float t36 = a.e2inf * b.scalar;
    const float t37 = a.e2inf * b.e12;
    const float t38 = a.e2inf * b.e13;
    const float t39 = a.e2inf * b.e23;
    const float t40 = a.e3inf * b.scalar;
    const float t41 = a.e3inf * b.e12;
    const float t42 = a.e3inf * b.e13;
    const float t43 = a.e3inf * b.e23;
    const float t44 = a.e123inf * b.scalar;
    const float t45 = a.e123inf * b.e12;
    const float t46 = a.e123inf * b.e13;
    const float t47 = a.e123inf * b.e23;
    g123inf_Motorf r;
    r.scalar = ((t0 - t9) - t18) - t27;
    r.e12 = ((t1 + t8) + t26) - t19;
    r.e13 = ((t2 + t11) + t16) - t25;
    r.e23 = ((t3 + t17) + t24) - t10;
    r.e1inf = ((((((t4 + t13) + t22) - t31) + t32) - t37) - t42) - t47;
    r.e2inf = ((((((t5 + t23) + t30) - t12) + t33) + t36) + t46) - t43;
    r.e3inf = ((((((t6 - t15) - t20) - t29) + t34) + t39) + t40) - t45;
    r.e123inf = ((((((t7 + t14) + t28) - t21) + t35) + t41) + t44) - t38;
    return r;
}

/* `gp` of a Motor and a Vector. */
static inline g123inf_Oddf g123inf_motor_gp_vectorf(g123inf_Motorf a, g123inf_Vectorf b) {
    const float t0 = a.scalar * b.e1;
    const float t1 = a.scalar * b.e2;
    const float t2 = a.scalar * b.e3;
    const float t3 = a.scalar * b.einf;
    const float t4 = a.e12 * b.e1;
    const float t5 = a.e12 * b.e2;
    const float t6 = a.e12 * b.e3;
    const float t7 = a.e12 * b.einf;
    const float t8 = a.e13 * b.e1;
    const float t9 = a.e13 * b.e2;
    const float t10 = a.e13 * b.e3;
    const float t11 = a.e13 * b.einf;
    const float t12 = a.e23 * b.e1;
    const float t13 = a.e23 * b.e2;
    const float t14 = a.e23 * b.e3;
    const float t15 = a.e23 * b.einf;
    const float t16 = a.e1inf * b.e1;
    const float t17 = a.e1inf * b.e2;
    const float t18 = a.e1inf * b.e3;
    const float t19 = a.e2inf * b.e1;
    const float t20 = a.e2inf * b.e2;
    const float t21 = a.e2inf * b.e3;
    const float t22 = a.e3inf * b.e1;
    const float t23 = a.e3inf * b.e2;
    const float t24 = a.e3inf * b.e3;
    const float t25 = a.e123inf * b.e1;
    const float t26 = a.e123inf * b.e2;
    const float t27 = a.e123inf * b.e3;
    g123inf_Oddf r;
    r.e1 = (t0 + t5) + t10;
    r.e2 = (t1 - t4) + t14;
    r.e3 = (t2 - t8) - t13;
    r.einf = ((t3 - t16) - t20) - t24;
    r.e123 = (t6 - t9) + t12;
    r.e12inf = ((t7 - t17) + t19) - t27;
    r.e13inf = ((t11 - t18) + t22) + t26;
    r.e23inf = ((t15 - t21) + t23) - t25;
    return r;
}

/* `gp` of a Motor and a Bivector. */
static inline g123inf_Motorf g123inf_motor_gp_bivectorf(g123inf_Motorf a, g123inf_Bivectorf b) {
    const float t0 = a.scalar * b.e12;
    const float t1 = a.scalar * b.e13;
    const float t2 = a.scalar * b.e23;
    const float t3 = a.scalar * b.e1inf;
    const float t4 = a.scalar * b.e2inf;
    const float t5 = a.scalar * b.e3inf;
    const float t6 = a.e12 * b.e12;
    const float t7 = a.e12 * b.e13;
    const float t8 = a.e12 * b.e23;
    const float t9 = a.e12 * b.e1inf;
    const float t10 = a.e12 * b.e2inf;
    const float t11 = a.e12 * b.e3inf;
    const float t12 = a.e13 * b.e12;
    const float t13 = a.e13 * b.e13;
    const float t14 = a.e13 * b.e23;
    const float t15 = a.e13 * b.e1inf;
    const float t16 = a.e13 * b.e2inf;
    const float t17 = a.e13 * b.e3inf;
    const float t18 = a.e23 * b.e12;
    const float t19 = a.e23 * b.e13;
    const float t20 = a.e23 * b.e23;
    const float t21 = a.e23 * b.e1inf;
    const float t22 = a.e23 * b.e2inf;
    const float t23 = a.e23 * b.e3inf;
    const float t24 = a.e1inf * b.e12;
    const float t25 = a.e1inf * b.e13;
    const float t26 = a.e1inf * b.e23;
    const float t27 = a.e2inf * b.e12;
    const float t28 = a.e2inf * b.e13;
    const float t29 = a.e2inf * b.e23;
    const float t30 = a.e3inf * b.e12;
    const float t31 = a.e3inf * b.e13;
    const float t32 = a.e3inf * b.e23;
    const float t33 = a.e123inf * b.e12;
    const float t34 = a.e123inf * b.e13;
    const float t35 = a.e123inf * b.e23;
    g123inf_Motorf r;
    r.scalar = ((-t6) - t13) - t20;
    r.e12 = (t0 - t14) + t19;
    r.e13 = (t1 + t8) - t18;
    r.e23 = (t2 - t7) + t12;
    r.e1inf = (((t3 + t10) + t17) - t27) - (t31 + t35);
    r.e2inf = (((t4 - t9) + t23) + t24) - (t32 - t34);
    r.e3inf = (((t5 - t15) - t22) + t25) + (t29 - t33);
    r.e123inf = (((t11 - t16) + t21) + t26) - (t28 - t30);
    return r;
}

/* `gp` of a Vector and a Motor. */
static inline g123inf_Oddf g123inf_vector_gp_motorf(g123inf_Vectorf a, g123inf_Motorf b) {
    const float t0 = a.e1 * b.scalar;
    const float t1 = a.e1 * b.e12;
    const float t2 = a.e1 * b.e13;
    const float t3 = a.e1 * b.e23;
    const float t4 = a.e1 * b.e1inf;
    const float t5 = a.e1 * b.e2inf;
    const float t6 = a.e1 * b.e3inf;
    const float t7 = a.e1 * b.e123inf;
    const float t8 = a.e2 * b.scalar;
    const float t9 = a.e2 * b.e12;
    const float t10 = a.e2 * b.e13;
    const float t11 = a.e2 * b.e23;
    const float t12 = a.e2 * b.e1inf;
    const float t13 = a.e2 * b.e2inf;
    const float t14 = a.e2 * b.e3inf;
    const float t15 = a.e2 * b.e123inf;
    const float t16 = a.e3 * b.scalar;
    const float t17 = a.e3 * b.e12;
    const float t18 = a.e3 * b.e13;
    const float t19 = a.e3 * b.e23;
    const float t20 = a.e3 * b.e1inf;
    const float t21 = a.e3 * b.e2inf;
    const float t22 = a.e3 * b.e3inf;
    const float t23 = a.e3 * b.e123inf;
    const float t24 = a.einf * b.scalar;
    const float t25 = a.einf * b.e12;
    const float t26 = a.einf * b.e13;
    const float t27 = a.einf * b.e23;
    g123inf_Oddf r;
    r.e1 = (t0 - t9) - t18;
    r.e2 = (t1 + t8) - t19;
    r.e3 = (t2 + t11) + t16;
    r.einf = ((t4 + t13) + t22) + t24;
    r.e123 = (t3 - t10) + t17;
    r.e12inf = ((t5 - t12) + t23) + t25;
    r.e13inf = ((t6 - t15) - t20) + t26;
    r.e23inf = ((t7 + t14) - t21) + t27;
    return r;
}

/* `gp` of a Vector and a Vector. */
static inline g123inf_Motorf g123inf_vector_gp_vectorf(g123inf_Vectorf a, g123inf_Vectorf b) {
    const float t0 = a.e1 * b.e1;
    const float t1 = a.e1 * b.e2;
    const float t2 = a.e1 * b.e3;
    const float t3 = a.e1 * b.einf;
    const float t4 = a.e2 * b.e1;
    const float t5 = a.e2 * b.e2;
    const float t6 = a.e2 * b.e3;
    const float t7 = a.e2 * b.einf;
    const float t8 = a.e3 * b.e1;
    const float t9 = a.e3 * b.e2;
    const float t10 = a.e3 * b.e3;
    const float t11 = a.e3 * b.einf;
    const float t12 = a.einf * b.e1;
    const float t13 = a.einf * b.e2;
    const float t14 = a.einf * b.e3;
    g123inf_Motorf r;
    r.scalar = (t0 + t5) + t10;
    r.e12 = t1 - t4;
    r.e13 = t2 - t8;
    r.e23 = t6 - t9;
    r.e1inf = t3 - t12;
    r.e2inf = t7 - t13;
    r.e3inf = t11 - t14;
    r.e123inf = 0.0f;
    return r;
}

/* `gp` of a Vector and a Bivector. */
static inline g123inf_Oddf g123inf_vector_gp_bivectorf(g123inf_Vectorf a, g123inf_Bivectorf b) {
    const float t0 = a.e1 * b.e12;
    const float t1 = a.e1 * b.e13;
    const float t2 = a.e1 * b.e23;
    const float t3 = a.e1 * b.e1inf;
    const float t4 = a.e1 * b.e2inf;
    const float t5 = a.e1 * b.e3inf;
    const float t6 = a.e2 * b.e12;
    const float t7 = a.e2 * b.e13;
    const float t8 = a.e2 * b.e23;
    const float t9 = a.e2 * b.e1inf;
    const float t10 = a.e2 * b.e2inf;
    const float t11 = a.e2 * b.e3inf;
    const float t12 = a.e3 * b.e12;
    const float t13 = a.e3 * b.e13;
    const float t14 = a.e3 * b.e23;
    const float t15 = a.e3 * b.e1inf;
    const float t16 = a.e3 * b.e2inf;
    const float t17 = a.e3 * b.e3inf;
    const float t18 = a.einf * b.e12;
    const float t19 = a.einf * b.e13;
    const float t20 = a.einf * b.e23;
    g123inf_Oddf r;
    r.e1 = (-t6) - t13;
    r.e2 = t0 - t14;
    r.e3 = t1 + t8;
    r.einf = (t3 + t10) + t17;
    r.e123 = (t2 - t7) + t12;
    r.e12inf = (t4 - t9) + t18;
    r.e13inf = (t5 - t15) + t19;
    r.e23inf = (t11 - t16) + t20;
    return r;
}

/* `gp` of a Bivector and a Motor. */
static inline g123inf_Motorf g123inf_bivector_gp_motorf(g123inf_Bivectorf a, g123inf_Motorf b) {
    const float t0 = a.e12 * b.scalar;
    const float t1 = a.e12 * b.e12;
    const float t2 = a.e12 * b.e13;
    const float t3 = a.e12 * b.e23;
    const float t4 = a.e12 * b.e1inf;
    const float t5 = a.e12 * b.e2inf;
    const float t6 = a.e12 * b.e3inf;
    const float t7 = a.e12 * b.e123inf;
    const float t8 = a.e13 * b.scalar;
    const float t9 = a.e13 * b.e12;
    const float t10 = a.e13 * b.e13;
    const float t11 = a.e13 * b.e23;
    const float t12 = a.e13 * b.e1inf;
    const float t13 = a.e13 * b.e2inf;
    const float t14 = a.e13 * b.e3inf;
    const float t15 = a.e13 * b.e123inf;
    const float t16 = a.e23 * b.scalar;
    const float t17 = a.e23 * b.e12;
    const float t18 = a.e23 * b.e13;
    const float t19 = a.e23 * b.e23;
    const float t20 = a.e23 * b.e1inf;
    const float t21 = a.e23 * b.e2inf;
    const float t22 = a.e23 * b.e3inf;
    const float t23 = a.e23 * b.e123inf;
    const float t24 = a.e1inf * b.scalar;
    const float t25 = a.e1inf * b.e12;
    const float t26 = a.e1inf * b.e13;
    const float t27 = a.e1inf * b.e23;
    const float t28 = a.e2inf * b.scalar;
    const float t29 = a.e2inf * b.e12;
    const float t30 = a.e2inf * b.e13;
    const float t31 = a.e2inf * b.e23;
    const float t32 = a.e3inf * b.scalar;
    const float t33 = a.e3inf * b.e12;
    const float t34 = a.e3inf * b.e13;
    const float t35 = a.e3inf * b.e23;
    g123inf_Motorf r;
    r.scalar = ((-t1) - t10) - t19;
    r.e12 = (t0 - t11) + t18;
    r.e13 = (t3 + t8) - t17;
    r.e23 = (t9 - t2) + t16;
    r.e1inf = (((t5 + t14) - t23) + t24) - (t29 + t34);
    r.e2inf = (((t15 - t4) + t22) + t25) + (t28 - t35);
    r.e3inf = (((t26 - t12) - t21) - t7) + (t31 + t32);
    r.e123inf = (((t6 - t13) + t20) + t27) - (t30 - t33);
    return r;
}

/* `gp` of a Bivector and a Vector. */
static inline g123inf_Oddf g123inf_bivector_gp_vectorf(g123inf_Bivectorf a, g123inf_Vectorf b) {
    const float t0 = a.e12 * b.e1;
    const float t1 = a.e12 * b.e2;
    const float t2 = a.e12 * b.e3;
    const float t3 = a.e12 * b.einf;
    const float t4 = a.e13 * b.e1;
    const float t5 = a.e13 * b.e2;
    const float t6 = a.e13 * b.e3;
    const float t7 = a.e13 * b.einf;
    const float t8 = a.e23 * b.e1;
    const float t9 = a.e23 * b.e2;
    const float t10 = a.e23 * b.e3;
    const float t11 = a.e23 * b.einf;
    const float t12 = a.e1inf * b.e1;
    const float t13 = a.e1inf * b.e2;
    const float t14 = a.e1inf * b.e3;
    const float t15 = a.e2inf * b.e1;
    const float t16 = a.e2inf * b.e2;
    const float t17 = a.e2inf * b.e3;
    const float t18 = a.e3inf * b.e1;
    const float t19 = a.e3inf * b.e2;
    const float t20 = a.e3inf * b.e3;
    g123inf_Oddf r;
    r.e1 = t1 + t6;
    r.e2 = t10 - t0;
    r.e3 = (-t4) - t9;
    r.einf = ((-t12) - t16) - t20;
    r.e123 = (t2 - t5) + t8;
    r.e12inf = (t3 - t13) + t15;
    r.e13inf = (t7 - t14) + t18;
    r.e23inf = (t11 - t17) + t19;
    return r;
}

/* `gp` of a Bivector and a Bivector. */
static inline g123inf_Motorf g123inf_bivector_gp_bivectorf(g123inf_Bivectorf a, g123inf_Bivectorf b) {
    const float t0 = a.e12 * b.e12;
    const float t1 = a.e12 * b.e13;
    const float t2 = a.e12 * b.e23;
    const float t3 = a.e12 * b.e1inf;
    const float t4 = a.e12 * b.e2inf;
    const float t5 = a.e12 * b.e3inf;
    const float t6 = a.e13 * b.e12;
    const float t7 = a.e13 * b.e13;
    const float t8 = a.e13 * b.e23;
    const float t9 = a.e13 * b.e1inf;
    const float t10 = a.e13 * b.e2inf;
    const float t11 = a.e13 * b.e3inf;
    const float t12 = a.e23 * b.e12;
    const float t13 = a.e23 * b.e13;
    const float t14 = a.e23 * b.e23;
    const float t15 = a.e23 * b.e1inf;
    const float t16 = a.e23 * b.e2inf;
    const float t17 = a.e23 * b.e3inf;
    const float t18 = a.e1inf * b.e12;
    const float t19 = a.e1inf * b.e13;
    const float t20 = a.e1inf * b.e23;
    const float t21 = a.e2inf * b.e12;
    const float t22 = a.e2inf * b.e13;
    const float t23 = a.e2inf * b.e23;
    const float t24 = a.e3inf * b.e12;
    const float t25 = a.e3inf * b.e13;
    const float t26 = a.e3inf * b.e23;
    g123inf_Motorf r;
    r.scalar = ((-t0) - t7) - t14;
    r.e12 = t13 - t8;
    r.e13 = t2 - t12;
    r.e23 = t6 - t1;
    r.e1inf = ((t4 + t11) - t21) - t25;
    r.e2inf = ((t17 - t3) + t18) - t26;
    r.e3inf = ((t19 - t16) - t9) + t23;
    r.e123inf = (((t5 - t10) + t15) + t20) - (t22 - t24);
    return r;
}

/* The reverse of a Motor. */
static inline g123inf_Motorf g123inf_motor_reversef(g123inf_Motorf x) {
    g123inf_Motorf r;
    r.scalar = x.scalar;
    r.e12 = -x.e12;
    r.e13 = -x.e13;
    r.e23 = -x.e23;
    r.e1inf = -x.e1inf;
    r.e2inf = -x.e2inf;
    r.e3inf = -x.e3inf;
    r.e123inf = x.e123inf;
    return r;
}

/* The squared norm <x rev(x)>_0 of a Motor (may be negative or zero). */
static inline float g123inf_motor_norm_squaredf(g123inf_Motorf x) {
    const float t0 = x.scalar * x.scalar;
    const float t1 = x.e12 * x.e12;
    const float t2 = x.e13 * x.e13;
    const float t3 = x.e23 * x.e23;
    return ((t0 + t1) + t2) + t3;
}

/* The reverse of a Vector. */
static inline g123inf_Vectorf g123inf_vector_reversef(g123inf_Vectorf x) {
    g123inf_Vectorf r;
    r.e1 = x.e1;
    r.e2 = x.e2;
    r.e3 = x.e3;
    r.einf = x.einf;
    return r;
}

/* The squared norm <x rev(x)>_0 of a Vector (may be negative or zero). */
static inline float g123inf_vector_norm_squaredf(g123inf_Vectorf x) {
    const float t0 = x.e1 * x.e1;
    const float t1 = x.e2 * x.e2;
    const float t2 = x.e3 * x.e3;
    return (t0 + t1) + t2;
}

/* The reverse of a Bivector. */
static inline g123inf_Bivectorf g123inf_bivector_reversef(g123inf_Bivectorf x) {
    g123inf_Bivectorf r;
    r.e12 = -x.e12;
    r.e13 = -x.e13;
    r.e23 = -x.e23;
    r.e1inf = -x.e1inf;
    r.e2inf = -x.e2inf;
    r.e3inf = -x.e3inf;
    return r;
}

/* The squared norm <x rev(x)>_0 of a Bivector (may be negative or zero). */
static inline float g123inf_bivector_norm_squaredf(g123inf_Bivectorf x) {
    const float t0 = x.e12 * x.e12;
    const float t1 = x.e13 * x.e13;
    const float t2 = x.e23 * x.e23;
    return (t0 + t1) + t2;
}

/* rev(S) x S for a Motor S and a Motor x, in one fused kernel. */
static inline g123inf_Motorf g123inf_motor_sandwich_motorf(g123inf_Motorf s, g123inf_Motorf x) {
    const float t0 = ((s.scalar * x.scalar) + (s.e12 * x.e12)) + ((s.e13 * x.e13) + (s.e23 * x.e23));
    const float t1 = ((s.scalar * x.e12) + (s.e13 * x.e23)) - ((s.e12 * x.scalar) + (s.e23 * x.e13));
    const float t2 = ((s.scalar * x.e13) + (s.e23 * x.e12)) - ((s.e12 * x.e23) + (s.e13 * x.scalar));
    const float t3 = ((s.scalar * x.e23) + (s.e12 * x.e13)) - ((s.e13 * x.e12) + (s.e23 * x.scalar));
    const float t4 = (((s.scalar * x.e1inf) + (s.e23 * x.e123inf)) + ((s.e2inf * x.e12) + (s.e3inf * x.e13))) - (((s.e12 * x.e2inf) + (s.e13 * x.e3inf)) + ((s.e1inf * x.scalar) + (s.e123inf * x.e23)));
    const float t5 = (((s.scalar * x.e2inf) + (s.e12 * x.e1inf)) + ((s.e3inf * x.e23) + (s.e123inf * x.e13))) - (((s.e13 * x.e123inf) + (s.e23 * x.e3inf)) + ((s.e1inf * x.e12) + (s.e2inf * x.scalar)));
    const float t6 = (((s.scalar * x.e3inf) + (s.e12 * x.e123inf)) + ((s.e13 * x.e1inf) + (s.e23 * x.e2inf))) - (((s.e1inf * x.e13) + (s.e2inf * x.e23)) + ((s.e3inf * x.scalar) + (s.e123inf * x.e12)));
    const float t7 = (((s.scalar * x.e123inf) + (s.e13 * x.e2inf)) + ((s.e2inf * x.e13) + (s.e123inf * x.scalar))) - (((s.e12 * x.e3inf) + (s.e23 * x.e1inf)) + ((s.e1inf * x.e23) + (s.e3inf * x.e12)));
    g123inf_Motorf r;
    r.scalar = ((t0 * s.scalar) - (t1 * s.e12)) - ((t2 * s.e13) + (t3 * s.e23));
    r.e12 = ((t1 * s.scalar) + (t0 * s.e12)) + ((t3 * s.e13) - (t2 * s.e23));
    r.e13 = ((t2 * s.scalar) - (t3 * s.e12)) + ((t0 * s.e13) + (t1 * s.e23));
    r.e23 = ((t3 * s.scalar) + (t2 * s.e12)) - ((t1 * s.e13) - (t0 * s.e23));
    r.e1inf = (((t4 * s.scalar) - (t5 * s.e12)) - ((t6 * s.e13) + (t7 * s.e23))) + (((t0 * s.e1inf) + (t1 * s.e2inf)) + ((t2 * s.e3inf) - (t3 * s.e123inf)));
    r.e2inf = (((t5 * s.scalar) + (t4 * s.e12)) + ((t7 * s.e13) - (t6 * s.e23))) - (((t1 * s.e1inf) - (t0 * s.e2inf)) - ((t3 * s.e3inf) + (t2 * s.e123inf)));
    r.e3inf = (((t6 * s.scalar) - (t7 * s.e12)) + ((t4 * s.e13) + (t5 * s.e23))) - (((t2 * s.e1inf) + (t3 * s.e2inf)) - ((t0 * s.e3inf) - (t1 * s.e123inf)));
    r.e123inf = (((t7 * s.scalar) + (t6 * s.e12)) - ((t5 * s.e13) - (t4 * s.e23))) + (((t3 * s.e1inf) - (t2 * s.e2inf)) + ((t1 * s.e3inf) + (t0 * s.e123inf)));
    return r;
}

/* rev(S) x S for a Motor S and a Vector x, in one fused kernel. */
static inline g123inf_Vectorf g123inf_motor_sandwich_vectorf(g123inf_Motorf s, g123inf_Vectorf x) {
    const float t0 = -((s.e12 * x.e2) + (s.e13 * x.e3));
    const float t1 = (s.e12 * x.e1) - (s.e23 * x.e3);
    const float t2 = (s.e13 * x.e1) + (s.e23 * x.e2);
    const float t3 = (s.e1inf * x.e1) + ((s.e2inf * x.e2) + (s.e3inf * x.e3));
    const float t4 = -(s.e123inf * x.e3);
    const float t5 = s.e123inf * x.e2;
    const float t6 = -(s.e123inf * x.e1);
    const float t7 = ((s.scalar * s.scalar) + (s.e12 * s.e12)) + ((s.e13 * s.e13) + (s.e23 * s.e23));
    const float t8 = (t0 * s.scalar) - ((t1 * s.e12) + (t2 * s.e13));
    const float t9 = (t1 * s.scalar) + ((t0 * s.e12) - (t2 * s.e23));
    const float t10 = (t2 * s.scalar) + ((t0 * s.e13) + (t1 * s.e23));
    const float t11 = ((t3 * s.scalar) - ((t4 * s.e12) + (t5 * s.e13))) - (((t6 * s.e23) - (t0 * s.e1inf)) - ((t1 * s.e2inf) + (t2 * s.e3inf)));
    g123inf_Vectorf r;
    r.e1 = (t7 * x.e1) + (t8 + t8);
    r.e2 = (t7 * x.e2) + (t9 + t9);
    r.e3 = (t7 * x.e3) + (t10 + t10);
    r.einf = (t7 * x.einf) + (t11 + t11);
    return r;
}

/* rev(S) x S for a Motor S and a Bivector x, in one fused kernel. */
static inline g123inf_Bivectorf g123inf_motor_sandwich_bivectorf(g123inf_Motorf s, g123inf_Bivectorf x) {
    const float t0 = (s.e12 * x.e12) + ((s.e13 * x.e13) + (s.e23 * x.e23));
    const float t1 = (s.scalar * x.e12) + ((s.e13 * x.e23) - (s.e23 * x.e13));
    const float t2 = (s.scalar * x.e13) + ((s.e23 * x.e12) - (s.e12 * x.e23));
    const float t3 = (s.scalar * x.e23) + ((s.e12 * x.e13) - (s.e13 * x.e12));
    const float t4 = ((s.scalar * x.e1inf) + ((s.e2inf * x.e12) + (s.e3inf * x.e13))) - ((s.e12 * x.e2inf) + ((s.e13 * x.e3inf) + (s.e123inf * x.e23)));
    const float t5 = ((s.scalar * x.e2inf) + ((s.e12 * x.e1inf) + (s.e3inf * x.e23))) + ((s.e123inf * x.e13) - ((s.e23 * x.e3inf) + (s.e1inf * x.e12)));
    const float t6 = ((s.scalar * x.e3inf) + ((s.e13 * x.e1inf) + (s.e23 * x.e2inf))) - ((s.e1inf * x.e13) + ((s.e2inf * x.e23) + (s.e123inf * x.e12)));
    const float t7 = ((s.e13 * x.e2inf) + ((s.e2inf * x.e13) - (s.e12 * x.e3inf))) - ((s.e23 * x.e1inf) + ((s.e1inf * x.e23) + (s.e3inf * x.e12)));
    g123inf_Bivectorf r;
    r.e12 = ((t1 * s.scalar) + (t0 * s.e12)) + ((t3 * s.e13) - (t2 * s.e23));
    r.e13 = ((t2 * s.scalar) - (t3 * s.e12)) + ((t0 * s.e13) + (t1 * s.e23));
    r.e23 = ((t3 * s.scalar) + (t2 * s.e12)) - ((t1 * s.e13) - (t0 * s.e23));
    r.e1inf = (((t4 * s.scalar) - (t5 * s.e12)) - ((t6 * s.e13) + (t7 * s.e23))) + (((t0 * s.e1inf) + (t1 * s.e2inf)) + ((t2 * s.e3inf) - (t3 * s.e123inf)));
    r.e2inf = (((t5 * s.scalar) + (t4 * s.e12)) + ((t7 * s.e13) - (t6 * s.e23))) - (((t1 * s.e1inf) - (t0 * s.e2inf)) - ((t3 * s.e3inf) + (t2 * s.e123inf)));
    r.e3inf = (((t6 * s.scalar) - (t7 * s.e12)) + ((t4 * s.e13) + (t5 * s.e23))) - (((t2 * s.e1inf) + (t3 * s.e2inf)) - ((t0 * s.e3inf) - (t1 * s.e123inf)));
    return r;
}

/* rev(S) x S for a Vector S and a Motor x, in one fused kernel. */
static inline g123inf_Motorf g123inf_vector_sandwich_motorf(g123inf_Vectorf s, g123inf_Motorf x) {
    const float t0 = (s.e1 * x.scalar) - ((s.e2 * x.e12) + (s.e3 * x.e13));
    const float t1 = (s.e1 * x.e12) + ((s.e2 * x.scalar) - (s.e3 * x.e23));
    const float t2 = (s.e1 * x.e13) + ((s.e2 * x.e23) + (s.e3 * x.scalar));
    const float t3 = (s.e1 * x.e23) + ((s.e3 * x.e12) - (s.e2 * x.e13));
    const float t4 = ((s.e1 * x.e1inf) + (s.e2 * x.e2inf)) + ((s.e3 * x.e3inf) + (s.einf * x.scalar));
    const float t5 = ((s.e1 * x.e2inf) + (s.e3 * x.e123inf)) + ((s.einf * x.e12) - (s.e2 * x.e1inf));
    const float t6 = ((s.e1 * x.e3inf) + (s.einf * x.e13)) - ((s.e2 * x.e123inf) + (s.e3 * x.e1inf));
    const float t7 = ((s.e1 * x.e123inf) + (s.e2 * x.e3inf)) + ((s.einf * x.e23) - (s.e3 * x.e2inf));
    g123inf_Motorf r;
    r.scalar = (t0 * s.e1) + ((t1 * s.e2) + (t2 * s.e3));
    r.e12 = (t0 * s.e2) - ((t1 * s.e1) - (t3 * s.e3));
    r.e13 = (t0 * s.e3) - ((t2 * s.e1) + (t3 * s.e2));
    r.e23 = (t3 * s.e1) - ((t2 * s.e2) - (t1 * s.e3));
    r.e1inf = ((t0 * s.einf) - (t4 * s.e1)) - ((t5 * s.e2) + (t6 * s.e3));
    r.e2inf = ((t5 * s.e1) - (t4 * s.e2)) - ((t7 * s.e3) - (t1 * s.einf));
    r.e3inf = ((t6 * s.e1) + (t7 * s.e2)) - ((t4 * s.e3) - (t2 * s.einf));
    r.e123inf = ((t6 * s.e2) - (t7 * s.e1)) - ((t5 * s.e3) - (t3 * s.einf));
    return r;
}

/* rev(S) x S for a Vector S and a Vector x, in one fused kernel. */
static inline g123inf_Vectorf g123inf_vector_sandwich_vectorf(g123inf_Vectorf s, g123inf_Vectorf x) {
    const float t0 = (s.e1 * x.e1) + ((s.e2 * x.e2) + (s.e3 * x.e3));
    const float t1 = (s.e1 * x.e2) - (s.e2 * x.e1);
    const float t2 = (s.e1 * x.e3) - (s.e3 * x.e1);
    const float t3 = (s.e2 * x.e3) - (s.e3 * x.e2);
    const float t4 = (s.e1 * x.einf) - (s.einf * x.e1);
    const float t5 = (s.e2 * x.einf) - (s.einf * x.e2);
    const float t6 = (s.e3 * x.einf) - (s.einf * x.e3);
    g123inf_Vectorf r;
    r.e1 = (t0 * s.e1) + ((t1 * s.e2) + (t2 * s.e3));
    r.e2 = (t0 * s.e2) - ((t1 * s.e1) - (t3 * s.e3));
    r.e3 = (t0 * s.e3) - ((t2 * s.e1) + (t3 * s.e2));
    r.einf = ((t0 * s.einf) - (t4 * s.e1)) - ((t5 * s.e2) + (t6 * s.e3));
    return r;
}

/* rev(S) x S for a Vector S and a Bivector x, in one fused kernel. */
static inline g123inf_Bivectorf g123inf_vector_sandwich_bivectorf(g123inf_Vectorf s, g123inf_Bivectorf x) {
    const float t0 = -((s.e2 * x.e12) + (s.e3 * x.e13));
    const float t1 = (s.e1 * x.e12) - (s.e3 * x.e23);
    const float t2 = (s.e1 * x.e13) + (s.e2 * x.e23);
    const float t3 = (s.e1 * x.e1inf) + ((s.e2 * x.e2inf) + (s.e3 * x.e3inf));
    const float t4 = (s.e1 * s.e1) + ((s.e2 * s.e2) + (s.e3 * s.e3));
    const float t5 = (t0 * s.e2) - (t1 * s.e1);
    const float t6 = (t0 * s.e3) - (t2 * s.e1);
    const float t7 = (t1 * s.e3) - (t2 * s.e2);
    const float t8 = (t0 * s.einf) - (t3 * s.e1);
    const float t9 = (t1 * s.einf) - (t3 * s.e2);
    const float t10 = (t2 * s.einf) - (t3 * s.e3);
    g123inf_Bivectorf r;
    r.e12 = (t4 * x.e12) + (t5 + t5);
    r.e13 = (t4 * x.e13) + (t6 + t6);
    r.e23 = (t4 * x.e23) + (t7 + t7);
    r.e1inf = (t4 * x.e1inf) + (t8 + t8);
    r.e2inf = (t4 * x.e2inf) + (t9 + t9);
    r.e3inf = (t4 * x.e3inf) + (t10 + t10);
    return r;
}

/* rev(S) x S for a Bivector S and a Motor x, in one fused kernel. */
static inline g123inf_Motorf g123inf_bivector_sandwich_motorf(g123inf_Bivectorf s, g123inf_Motorf x) {
    const float t0 = (s.e12 * x.e12) + ((s.e13 * x.e13) + (s.e23 * x.e23));
    const float t1 = (s.e13 * x.e23) - ((s.e12 * x.scalar) + (s.e23 * x.e13));
    const float t2 = (s.e23 * x.e12) - ((s.e12 * x.e23) + (s.e13 * x.scalar));
    const float t3 = (s.e12 * x.e13) - ((s.e13 * x.e12) + (s.e23 * x.scalar));
    const float t4 = ((s.e23 * x.e123inf) + ((s.e2inf * x.e12) + (s.e3inf * x.e13))) - ((s.e12 * x.e2inf) + ((s.e13 * x.e3inf) + (s.e1inf * x.scalar)));
    const float t5 = ((s.e12 * x.e1inf) + ((s.e3inf * x.e23) - (s.e13 * x.e123inf))) - ((s.e23 * x.e3inf) + ((s.e1inf * x.e12) + (s.e2inf * x.scalar)));
    const float t6 = ((s.e12 * x.e123inf) + ((s.e13 * x.e1inf) + (s.e23 * x.e2inf))) - ((s.e1inf * x.e13) + ((s.e2inf * x.e23) + (s.e3inf * x.scalar)));
    const float t7 = ((s.e13 * x.e2inf) + ((s.e2inf * x.e13) - (s.e12 * x.e3inf))) - ((s.e23 * x.e1inf) + ((s.e1inf * x.e23) + (s.e3inf * x.e12)));
    g123inf_Motorf r;
    r.scalar = -((t1 * s.e12) + ((t2 * s.e13) + (t3 * s.e23)));
    r.e12 = (t0 * s.e12) + ((t3 * s.e13) - (t2 * s.e23));
    r.e13 = (t0 * s.e13) - ((t3 * s.e12) - (t1 * s.e23));
    r.e23 = (t2 * s.e12) - ((t1 * s.e13) - (t0 * s.e23));
    r.e1inf = ((t0 * s.e1inf) - ((t5 * s.e12) + (t6 * s.e13))) - ((t7 * s.e23) - ((t1 * s.e2inf) + (t2 * s.e3inf)));
    r.e2inf = ((t4 * s.e12) + ((t7 * s.e13) - (t6 * s.e23))) - ((t1 * s.e1inf) - ((t0 * s.e2inf) + (t3 * s.e3inf)));
    r.e3inf = ((t4 * s.e13) - ((t7 * s.e12) - (t5 * s.e23))) - ((t2 * s.e1inf) + ((t3 * s.e2inf) - (t0 * s.e3inf)));
    r.e123inf = ((t6 * s.e12) - ((t5 * s.e13) - (t4 * s.e23))) + ((t3 * s.e1inf) - ((t2 * s.e2inf) - (t1 * s.e3inf)));
    return r;
}

/* rev(S) x S for a Bivector S and a Vector x, in one fused kernel. */
static inline g123inf_Vectorf g123inf_bivector_sandwich_vectorf(g123inf_Bivectorf s, g123inf_Vectorf x) {
    const float t0 = -((s.e12 * x.e2) + (s.e13 * x.e3));
    const float t1 = (s.e12 * x.e1) - (s.e23 * x.e3);
    const float t2 = (s.e13 * x.e1) + (s.e23 * x.e2);
    const float t3 = (s.e12 * s.e12) + ((s.e13 * s.e13) + (s.e23 * s.e23));
    const float t4 = -((t1 * s.e12) + (t2 * s.e13));
    const float t5 = (t0 * s.e12) - (t2 * s.e23);
    const float t6 = (t0 * s.e13) + (t1 * s.e23);
    const float t7 = (t0 * s.e1inf) + ((t1 * s.e2inf) + (t2 * s.e3inf));
    g123inf_Vectorf r;
    r.e1 = (t3 * x.e1) + (t4 + t4);
    r.e2 = (t3 * x.e2) + (t5 + t5);
    r.e3 = (t3 * x.e3) + (t6 + t6);
    r.einf = (t3 * x.einf) + (t7 + t7);
    return r;
}

/* rev(S) x S for a Bivector S and a Bivector x, in one fused kernel. */
static inline g123inf_Bivectorf g123inf_bivector_sandwich_bivectorf(g123inf_Bivectorf s, g123inf_Bivectorf x) {
    const float t0 = (s.e12 * x.e12) + ((s.e13 * x.e13) + (s.e23 * x.e23));
    const float t1 = (s.e13 * x.e23) - (s.e23 * x.e13);
    const float t2 = (s.e23 * x.e12) - (s.e12 * x.e23);
    const float t3 = (s.e12 * x.e13) - (s.e13 * x.e12);
    const float t4 = ((s.e2inf * x.e12) + (s.e3inf * x.e13)) - ((s.e12 * x.e2inf) + (s.e13 * x.e3inf));
    const float t5 = ((s.e12 * x.e1inf) + (s.e3inf * x.e23)) - ((s.e23 * x.e3inf) + (s.e1inf * x.e12));
    const float t6 = ((s.e13 * x.e1inf) + (s.e23 * x.e2inf)) - ((s.e1inf * x.e13) + (s.e2inf * x.e23));
    const float t7 = ((s.e13 * x.e2inf) + ((s.e2inf * x.e13) - (s.e12 * x.e3inf))) - ((s.e23 * x.e1inf) + ((s.e1inf * x.e23) + (s.e3inf * x.e12)));
    g123inf_Bivectorf r;
    r.e12 = (t0 * s.e12) + ((t3 * s.e13) - (t2 * s.e23));
    r.e13 = (t0 * s.e13) - ((t3 * s.e12) - (t1 * s.e23));
    r.e23 = (t2 * s.e12) - ((t1 * s.e13) - (t0 * s.e23));
    r.e1inf = ((t0 * s.e1inf) - ((t5 * s.e12) + (t6 * s.e13))) - ((t7 * s.e23) - ((t1 * s.e2inf) + (t2 * s.e3inf)));
    r.e2inf = ((t4 * s.e12) + ((t7 * s.e13) - (t6 * s.e23))) - ((t1 * s.e1inf) - ((t0 * s.e2inf) + (t3 * s.e3inf)));
    r.e3inf = ((t4 * s.e13) - ((t7 * s.e12) - (t5 * s.e23))) - ((t2 * s.e1inf) + ((t3 * s.e2inf) - (t0 * s.e3inf)));
    return r;
}

/* rev(S) x S for a unit Motor S (S rev(S) = 1) and a Motor x; not the action otherwise. */
static inline g123inf_Motorf g123inf_motor_sandwich_unit_motorf(g123inf_Motorf s, g123inf_Motorf x) {
    const float t0 = (s.e13 * x.e23) - (s.e23 * x.e13);
    const float t1 = -((s.e12 * x.e23) - (s.e23 * x.e12));
    const float t2 = (s.e12 * x.e13) - (s.e13 * x.e12);
    const float t3 = -(((s.e12 * x.e2inf) + (s.e13 * x.e3inf)) - ((s.e2inf * x.e12) + (s.e3inf * x.e13)));
    const float t4 = ((s.e12 * x.e1inf) - (s.e23 * x.e3inf)) - ((s.e1inf * x.e12) - (s.e3inf * x.e23));
    const float t5 = ((s.e13 * x.e1inf) + (s.e23 * x.e2inf)) - ((s.e1inf * x.e13) + (s.e2inf * x.e23));
    const float t6 = (t0 * s.scalar) - ((t1 * s.e23) - (t2 * s.e13));
    const float t7 = (t0 * s.e23) + ((t1 * s.scalar) - (t2 * s.e12));
    const float t8 = -((t0 * s.e13) - ((t1 * s.e12) + (t2 * s.scalar)));
    const float t9 = ((t0 * s.e2inf) + ((t1 * s.e3inf) - (t2 * s.e123inf))) + ((t3 * s.scalar) - ((t4 * s.e12) + (t5 * s.e13)));
    const float t10 = -(((t0 * s.e1inf) - ((t1 * s.e123inf) + (t2 * s.e3inf))) - ((t3 * s.e12) + ((t4 * s.scalar) - (t5 * s.e23))));
    const float t11 = -(((t0 * s.e123inf) + ((t1 * s.e1inf) + (t2 * s.e2inf))) - ((t3 * s.e13) + ((t4 * s.e23) + (t5 * s.scalar))));
    g123inf_Motorf r;
    r.scalar = x.scalar;
    r.e12 = (x.e12 + t6) + t6;
    r.e13 = (x.e13 + t7) + t7;
    r.e23 = (x.e23 + t8) + t8;
    r.e1inf = (x.e1inf + t9) + t9;
    r.e2inf = (x.e2inf + t10) + t10;
    r.e3inf = (x.e3inf + t11) + t11;
    r.e123inf = x.e123inf;
    return r;
}

/* rev(S) x S for a unit Motor S (S rev(S) = 1) and a Vector x; not the action otherwise. */
static inline g123inf_Vectorf g123inf_motor_sandwich_unit_vectorf(g123inf_Motorf s, g123inf_Vectorf x) {
    const float t0 = -((s.e12 * x.e2) + (s.e13 * x.e3));
    const float t1 = (s.e12 * x.e1) - (s.e23 * x.e3);
    const float t2 = (s.e13 * x.e1) + (s.e23 * x.e2);
    const float t3 = (s.e1inf * x.e1) + ((s.e2inf * x.e2) + (s.e3inf * x.e3));
    const float t4 = -(s.e123inf * x.e3);
    const float t5 = s.e123inf * x.e2;
    const float t6 = -(s.e123inf * x.e1);
    const float t7 = (t0 * s.scalar) - ((t1 * s.e12) + (t2 * s.e13));
    const float t8 = (t0 * s.e12) + ((t1 * s.scalar) - (t2 * s.e23));
    const float t9 = (t0 * s.e13) + ((t1 * s.e23) + (t2 * s.scalar));
    const float t10 = ((t0 * s.e1inf) + ((t1 * s.e2inf) + (t2 * s.e3inf))) + (((t3 * s.scalar) - (t4 * s.e12)) - ((t5 * s.e13) + (t6 * s.e23)));
    g123inf_Vectorf r;
    r.e1 = (x.e1 + t7) + t7;
    r.e2 = (x.e2 + t8) + t8;
    r.e3 = (x.e3 + t9) + t9;
    r.einf = (x.einf + t10) + t10;
    return r;
}

/* rev(S) x S for a unit Motor S (S rev(S) = 1) and a Bivector x; not the action otherwise. */
static inline g123inf_Bivectorf g123inf_motor_sandwich_unit_bivectorf(g123inf_Motorf s, g123inf_Bivectorf x) {
    const float t0 = (s.e13 * x.e23) - (s.e23 * x.e13);
    const float t1 = -((s.e12 * x.e23) - (s.e23 * x.e12));
    const float t2 = (s.e12 * x.e13) - (s.e13 * x.e12);
    const float t3 = -(((s.e12 * x.e2inf) + (s.e13 * x.e3inf)) - ((s.e2inf * x.e12) + (s.e3inf * x.e13)));
    const float t4 = ((s.e12 * x.e1inf) - (s.e23 * x.e3inf)) - ((s.e1inf * x.e12) - (s.e3inf * x.e23));
    const float t5 = ((s.e13 * x.e1inf) + (s.e23 * x.e2inf)) - ((s.e1inf * x.e13) + (s.e2inf * x.e23));
    const float t6 = (t0 * s.scalar) - ((t1 * s.e23) - (t2 * s.e13));
    const float t7 = (t0 * s.e23) + ((t1 * s.scalar) - (t2 * s.e12));
    const float t8 = -((t0 * s.e13) - ((t1 * s.e12) + (t2 * s.scalar)));
    const float t9 = ((t0 * s.e2inf) + ((t1 * s.e3inf) - (t2 * s.e123inf))) + ((t3 * s.scalar) - ((t4 * s.e12) + (t5 * s.e13)));
    const float t10 = -(((t0 * s.e1inf) - ((t1 * s.e123inf) + (t2 * s.e3inf))) - ((t3 * s.e12) + ((t4 * s.scalar) - (t5 * s.e23))));
    const float t11 = -(((t0 * s.e123inf) + ((t1 * s.e1inf) + (t2 * s.e2inf))) - ((t3 * s.e13) + ((t4 * s.e23) + (t5 * s.scalar))));
    g123inf_Bivectorf r;
    r.e12 = (x.e12 + t6) + t6;
    r.e13 = (x.e13 + t7) + t7;
    r.e23 = (x.e23 + t8) + t8;
    r.e1inf = (x.e1inf + t9) + t9;
    r.e2inf = (x.e2inf + t10) + t10;
    r.e3inf = (x.e3inf + t11) + t11;
    return r;
}

/* rev(S) x S for a unit Vector S (S rev(S) = 1) and a Motor x; not the action otherwise. */
static inline g123inf_Motorf g123inf_vector_sandwich_unit_motorf(g123inf_Vectorf s, g123inf_Motorf x) {
    const float t0 = -((s.e2 * x.e12) + (s.e3 * x.e13));
    const float t1 = (s.e1 * x.e12) - (s.e3 * x.e23);
    const float t2 = (s.e1 * x.e13) + (s.e2 * x.e23);
    const float t3 = (s.e1 * x.e1inf) + ((s.e2 * x.e2inf) + (s.e3 * x.e3inf));
    const float t4 = s.e3 * x.e123inf;
    const float t5 = -(s.e2 * x.e123inf);
    const float t6 = s.e1 * x.e123inf;
    const float t7 = (t0 * s.e2) - (t1 * s.e1);
    const float t8 = (t0 * s.e3) - (t2 * s.e1);
    const float t9 = (t1 * s.e3) - (t2 * s.e2);
    const float t10 = ((t0 * s.einf) - (t3 * s.e1)) - ((t4 * s.e2) + (t5 * s.e3));
    const float t11 = ((t1 * s.einf) - (t3 * s.e2)) + ((t4 * s.e1) - (t6 * s.e3));
    const float t12 = ((t2 * s.einf) - (t3 * s.e3)) + ((t5 * s.e1) + (t6 * s.e2));
    const float t13 = -((t4 * s.e3) - ((t5 * s.e2) - (t6 * s.e1)));
    g123inf_Motorf r;
    r.scalar = x.scalar;
    r.e12 = (x.e12 + t7) + t7;
    r.e13 = (x.e13 + t8) + t8;
    r.e23 = (x.e23 + t9) + t9;
    r.e1inf = (x.e1inf + t10) + t10;
    r.e2inf = (x.e2inf + t11) + t11;
    r.e3inf = (x.e3inf + t12) + t12;
    r.e123inf = (x.e123inf + t13) + t13;
    return r;
}

/* rev(S) x S for a unit Vector S (S rev(S) = 1) and a Vector x; not the action otherwise. */
static inline g123inf_Vectorf g123inf_vector_sandwich_unit_vectorf(g123inf_Vectorf s, g123inf_Vectorf x) {
    const float t0 = (s.e1 * x.e2) - (s.e2 * x.e1);
    const float t1 = (s.e1 * x.e3) - (s.e3 * x.e1);
    const float t2 = (s.e2 * x.e3) - (s.e3 * x.e2);
    const float t3 = (s.e1 * x.einf) - (s.einf * x.e1);
    const float t4 = (s.e2 * x.einf) - (s.einf * x.e2);
    const float t5 = (s.e3 * x.einf) - (s.einf * x.e3);
    const float t6 = (t0 * s.e2) + (t1 * s.e3);
    const float t7 = -((t0 * s.e1) - (t2 * s.e3));
    const float t8 = -((t1 * s.e1) + (t2 * s.e2));
    const float t9 = -((t3 * s.e1) + ((t4 * s.e2) + (t5 * s.e3)));
    g123inf_Vectorf r;
    r.e1 = (x.e1 + t6) + t6;
    r.e2 = (x.e2 + t7) + t7;
    r.e3 = (x.e3 + t8) + t8;
    r.einf = (x.einf + t9) + t9;
    return r;
}

/* rev(S) x S for a unit Vector S (S rev(S) = 1) and a Bivector x; not the action otherwise. */
static inline g123inf_Bivectorf g123inf_vector_sandwich_unit_bivectorf(g123inf_Vectorf s, g123inf_Bivectorf x) {
    const float t0 = -((s.e2 * x.e12) + (s.e3 * x.e13));
    const float t1 = (s.e1 * x.e12) - (s.e3 * x.e23);
    const float t2 = (s.e1 * x.e13) + (s.e2 * x.e23);
    const float t3 = (s.e1 * x.e1inf) + ((s.e2 * x.e2inf) + (s.e3 * x.e3inf));
    const float t4 = (t0 * s.e2) - (t1 * s.e1);
    const float t5 = (t0 * s.e3) - (t2 * s.e1);
    const float t6 = (t1 * s.e3) - (t2 * s.e2);
    const float t7 = (t0 * s.einf) - (t3 * s.e1);
    const float t8 = (t1 * s.einf) - (t3 * s.e2);
    const float t9 = (t2 * s.einf) - (t3 * s.e3);
    g123inf_Bivectorf r;
    r.e12 = (x.e12 + t4) + t4;
    r.e13 = (x.e13 + t5) + t5;
    r.e23 = (x.e23 + t6) + t6;
    r.e1inf = (x.e1inf + t7) + t7;
    r.e2inf = (x.e2inf + t8) + t8;
    r.e3inf = (x.e3inf + t9) + t9;
    return r;
}

/* rev(S) x S for a unit Bivector S (S rev(S) = 1) and a Motor x; not the action otherwise. */
static inline g123inf_Motorf g123inf_bivector_sandwich_unit_motorf(g123inf_Bivectorf s, g123inf_Motorf x) {
    const float t0 = (s.e13 * x.e23) - (s.e23 * x.e13);
    const float t1 = -((s.e12 * x.e23) - (s.e23 * x.e12));
    const float t2 = (s.e12 * x.e13) - (s.e13 * x.e12);
    const float t3 = -(((s.e12 * x.e2inf) + (s.e13 * x.e3inf)) - ((s.e2inf * x.e12) + (s.e3inf * x.e13)));
    const float t4 = ((s.e12 * x.e1inf) - (s.e23 * x.e3inf)) - ((s.e1inf * x.e12) - (s.e3inf * x.e23));
    const float t5 = ((s.e13 * x.e1inf) + (s.e23 * x.e2inf)) - ((s.e1inf * x.e13) + (s.e2inf * x.e23));
    const float t6 = -((t1 * s.e23) - (t2 * s.e13));
    const float t7 = (t0 * s.e23) - (t2 * s.e12);
    const float t8 = -((t0 * s.e13) - (t1 * s.e12));
    const float t9 = ((t0 * s.e2inf) + (t1 * s.e3inf)) - ((t4 * s.e12) + (t5 * s.e13));
    const float t10 = -(((t0 * s.e1inf) - (t2 * s.e3inf)) - ((t3 * s.e12) - (t5 * s.e23)));
    const float t11 = -(((t1 * s.e1inf) + (t2 * s.e2inf)) - ((t3 * s.e13) + (t4 * s.e23)));
    g123inf_Motorf r;
    r.scalar = x.scalar;
    r.e12 = (x.e12 + t6) + t6;
    r.e13 = (x.e13 + t7) + t7;
    r.e23 = (x.e23 + t8) + t8;
    r.e1inf = (x.e1inf + t9) + t9;
    r.e2inf = (x.e2inf + t10) + t10;
    r.e3inf = (x.e3inf + t11) + t11;
    r.e123inf = x.e123inf;
    return r;
}

/* rev(S) x S for a unit Bivector S (S rev(S) = 1) and a Vector x; not the action otherwise. */
static inline g123inf_Vectorf g123inf_bivector_sandwich_unit_vectorf(g123inf_Bivectorf s, g123inf_Vectorf x) {
    const float t0 = -((s.e12 * x.e2) + (s.e13 * x.e3));
    const float t1 = (s.e12 * x.e1) - (s.e23 * x.e3);
    const float t2 = (s.e13 * x.e1) + (s.e23 * x.e2);
    const float t3 = -((t1 * s.e12) + (t2 * s.e13));
    const float t4 = (t0 * s.e12) - (t2 * s.e23);
    const float t5 = (t0 * s.e13) + (t1 * s.e23);
    const float t6 = (t0 * s.e1inf) + ((t1 * s.e2inf) + (t2 * s.e3inf));
    g123inf_Vectorf r;
    r.e1 = (x.e1 + t3) + t3;
    r.e2 = (x.e2 + t4) + t4;
    r.e3 = (x.e3 + t5) + t5;
    r.einf = (x.einf + t6) + t6;
    return r;
}

/* rev(S) x S for a unit Bivector S (S rev(S) = 1) and a Bivector x; not the action otherwise. */
static inline g123inf_Bivectorf g123inf_bivector_sandwich_unit_bivectorf(g123inf_Bivectorf s, g123inf_Bivectorf x) {
    const float t0 = (s.e13 * x.e23) - (s.e23 * x.e13);
    const float t1 = -((s.e12 * x.e23) - (s.e23 * x.e12));
    const float t2 = (s.e12 * x.e13) - (s.e13 * x.e12);
    const float t3 = -(((s.e12 * x.e2inf) + (s.e13 * x.e3inf)) - ((s.e2inf * x.e12) + (s.e3inf * x.e13)));
    const float t4 = ((s.e12 * x.e1inf) - (s.e23 * x.e3inf)) - ((s.e1inf * x.e12) - (s.e3inf * x.e23));
    const float t5 = ((s.e13 * x.e1inf) + (s.e23 * x.e2inf)) - ((s.e1inf * x.e13) + (s.e2inf * x.e23));
    const float t6 = -((t1 * s.e23) - (t2 * s.e13));
    const float t7 = (t0 * s.e23) - (t2 * s.e12);
    const float t8 = -((t0 * s.e13) - (t1 * s.e12));
    const float t9 = ((t0 * s.e2inf) + (t1 * s.e3inf)) - ((t4 * s.e12) + (t5 * s.e13));
    const float t10 = -(((t0 * s.e1inf) - (t2 * s.e3inf)) - ((t3 * s.e12) - (t5 * s.e23)));
    const float t11 = -(((t1 * s.e1inf) + (t2 * s.e2inf)) - ((t3 * s.e13) + (t4 * s.e23)));
    g123inf_Bivectorf r;
    r.e12 = (x.e12 + t6) + t6;
    r.e13 = (x.e13 + t7) + t7;
    r.e23 = (x.e23 + t8) + t8;
    r.e1inf = (x.e1inf + t9) + t9;
    r.e2inf = (x.e2inf + t10) + t10;
    r.e3inf = (x.e3inf + t11) + t11;
    return r;
}

/* exp of a Bivector: a unit Motor (closed form; non-finite input gives non-finite output). */
static inline g123inf_Motorf g123inf_bivector_expf(g123inf_Bivectorf x) {
    const float t0 = ((x.e12 * x.e12) + (x.e13 * x.e13)) + (x.e23 * x.e23);
    const g123inf_Triplef t1 = g123inf_exp_factorsf(t0);
    const float t2 = ((x.e12 * x.e3inf) - (x.e13 * x.e2inf)) + (x.e23 * x.e1inf);
    const float t3 = t2 * t1.y;
    g123inf_Motorf r;
    r.scalar = t1.z;
    r.e12 = t1.x * x.e12;
    r.e13 = t1.x * x.e13;
    r.e23 = t1.x * x.e23;
    r.e1inf = (t1.x * x.e1inf) + (t3 * x.e23);
    r.e2inf = (t1.x * x.e2inf) - (t3 * x.e13);
    r.e3inf = (t1.x * x.e3inf) + (t3 * x.e12);
    r.e123inf = t2 * t1.x;
    return r;
}

/* log of a unit Motor (m rev(m) = 1): the Bivector B with exp(B) = m, angle in [0, pi); a full turn gives non-finite output. */
static inline g123inf_Bivectorf g123inf_motor_log_unitf(g123inf_Motorf x) {
    const float t0 = sqrtf(((x.e12 * x.e12) + (x.e13 * x.e13)) + (x.e23 * x.e23));
    const g123inf_Triplef t1 = g123inf_log_factorsf(t0, x.scalar);
    const float t2 = x.e123inf * t1.y;
    g123inf_Bivectorf r;
    r.e12 = t1.x * x.e12;
    r.e13 = t1.x * x.e13;
    r.e23 = t1.x * x.e23;
    r.e1inf = (t1.x * x.e1inf) - (t2 * x.e23);
    r.e2inf = (t1.x * x.e2inf) + (t2 * x.e13);
    r.e3inf = (t1.x * x.e3inf) - (t2 * x.e12);
    return r;
}

/* m / sqrt(m rev(m)) for a Motor: a unit Motor; a non-positive norm gives non-finite output. */
static inline g123inf_Motorf g123inf_motor_normalizef(g123inf_Motorf x) {
    const float t0 = (x.scalar * x.scalar) - (((-(x.e12 * x.e12)) - (x.e13 * x.e13)) - (x.e23 * x.e23));
    const float t1 = 1.0f / t0;
    const float t2 = (x.scalar * x.e123inf) - (((x.e12 * x.e3inf) - (x.e13 * x.e2inf)) + (x.e23 * x.e1inf));
    const float t3 = sqrtf(t1);
    const float t4 = (-(t2 * t3)) * t1;
    g123inf_Motorf r;
    r.scalar = x.scalar * t3;
    r.e12 = x.e12 * t3;
    r.e13 = x.e13 * t3;
    r.e23 = x.e23 * t3;
    r.e1inf = (x.e1inf * t3) + (-(t4 * x.e23));
    r.e2inf = (x.e2inf * t3) + (t4 * x.e13);
    r.e3inf = (x.e3inf * t3) + (-(t4 * x.e12));
    r.e123inf = (x.e123inf * t3) + (x.scalar * t4);
    return r;
}

#endif /* GAM_G123INF_H */
