/* cga: Motor=even;Vector=grade1; ops sandwich_unit,reverse,norm_squared */
#ifndef GAM_CGA_H
#define GAM_CGA_H

/* Motor: the coefficients of scalar, e12, e13, e23, e14, e24, e34, e15, e25, e35, e45, e1234, e1235, e1245, e1345, e2345. */
typedef struct cga_Motor {
    double scalar;
    double e12;
    double e13;
    double e23;
    double e14;
    double e24;
    double e34;
    double e15;
    double e25;
    double e35;
    double e45;
    double e1234;
    double e1235;
    double e1245;
    double e1345;
    double e2345;
} cga_Motor;

/* Vector: the coefficients of e1, e2, e3, e4, e5. */
typedef struct cga_Vector {
    double e1;
    double e2;
    double e3;
    double e4;
    double e5;
} cga_Vector;

/* The reverse of a Motor. */
static inline cga_Motor cga_motor_reverse(cga_Motor x) {
    cga_Motor r;
    r.scalar = x.scalar;
    r.e12 = -x.e12;
    r.e13 = -x.e13;
    r.e23 = -x.e23;
    r.e14 = -x.e14;
    r.e24 = -x.e24;
    r.e34 = -x.e34;
    r.e15 = -x.e15;
    r.e25 = -x.e25;
    r.e35 = -x.e35;
    r.e45 = -x.e45;
    r.e1234 = x.e1234;
    r.e1235 = x.e1235;
    r.e1245 = x.e1245;
    r.e1345 = x.e1345;
    r.e2345 = x.e2345;
    return r;
}

/* The squared norm <x rev(x)>_0 of a Motor (may be negative or zero). */
static inline double cga_motor_norm_squared(cga_Motor x) {
    const double t0 = x.scalar * x.scalar;
    const double t1 = x.e12 * x.e12;
    const double t2 = x.e13 * x.e13;
    const double t3 = x.e23 * x.e23;
    const double t4 = x.e14 * x.e14;
    const double t5 = x.e24 * x.e24;
    const double t6 = x.e34 * x.e34;
    const double t7 = x.e15 * x.e15;
    const double t8 = x.e25 * x.e25;
    const double t9 = x.e35 * x.e35;
    const double t10 = x.e45 * x.e45;
    const double t11 = x.e1234 * x.e1234;
    const double t12 = x.e1235 * x.e1235;
    const double t13 = x.e1245 * x.e1245;
    const double t14 = x.e1345 * x.e1345;
    const double t15 = x.e2345 * x.e2345;
    return ((((((((((((((t0 + t1) + t2) + t3) + t4) + t5) + t6) - t7) - t8) - t9) - t10) + t11) - t12) - t13) - t14) - t15;
}

/* The reverse of a Vector. */
static inline cga_Vector cga_vector_reverse(cga_Vector x) {
    cga_Vector r;
    r.e1 = x.e1;
    r.e2 = x.e2;
    r.e3 = x.e3;
    r.e4 = x.e4;
    r.e5 = x.e5;
    return r;
}

/* The squared norm <x rev(x)>_0 of a Vector (may be negative or zero). */
static inline double cga_vector_norm_squared(cga_Vector x) {
    const double t0 = x.e1 * x.e1;
    const double t1 = x.e2 * x.e2;
    const double t2 = x.e3 * x.e3;
    const double t3 = x.e4 * x.e4;
    const double t4 = x.e5 * x.e5;
    return (((t0 + t1) + t2) + t3) - t4;
}

/* rev(S) x S for a Motor S and a Motor x, in one fused kernel. (the general action: this pair is above the size threshold) */
static inline cga_Motor cga_motor_sandwich_unit_motor(cga_Motor s, cga_Motor x) {
    const double t0 = (((((0.0 + (s.scalar * x.scalar)) + (s.e14 * x.e14)) - (s.e25 * x.e25)) - (s.e1235 * x.e1235)) + ((((0.0 + (s.e12 * x.e12)) + (s.e24 * x.e24)) - (s.e35 * x.e35)) - (s.e1245 * x.e1245))) + (((((0.0 + (s.e13 * x.e13)) + (s.e34 * x.e34)) - (s.e45 * x.e45)) - (s.e1345 * x.e1345)) + ((((0.0 + (s.e23 * x.e23)) - (s.e15 * x.e15)) + (s.e1234 * x.e1234)) - (s.e2345 * x.e2345)));
    const double t1 = (((((0.0 + (s.scalar * x.e12)) + (s.e14 * x.e24)) + (s.e25 * x.e15)) + (s.e1235 * x.e35)) + ((((0.0 - (s.e12 * x.scalar)) - (s.e24 * x.e14)) - (s.e35 * x.e1235)) + (s.e1245 * x.e45))) + (((((0.0 + (s.e13 * x.e23)) + (s.e34 * x.e1234)) - (s.e45 * x.e1245)) - (s.e1345 * x.e2345)) + ((((0.0 - (s.e23 * x.e13)) - (s.e15 * x.e25)) - (s.e1234 * x.e34)) + (s.e2345 * x.e1345)));
    const double t2 = (((((0.0 + (s.scalar * x.e13)) + (s.e14 * x.e34)) + (s.e25 * x.e1235)) - (s.e1235 * x.e25)) + ((((0.0 - (s.e12 * x.e23)) - (s.e24 * x.e1234)) + (s.e35 * x.e15)) + (s.e1245 * x.e2345))) + (((((0.0 - (s.e13 * x.scalar)) - (s.e34 * x.e14)) - (s.e45 * x.e1345)) + (s.e1345 * x.e45)) + ((((0.0 + (s.e23 * x.e12)) - (s.e15 * x.e35)) + (s.e1234 * x.e24)) - (s.e2345 * x.e1245)));
    const double t3 = (((((0.0 + (s.scalar * x.e23)) + (s.e14 * x.e1234)) - (s.e25 * x.e35)) + (s.e1235 * x.e15)) + ((((0.0 + (s.e12 * x.e13)) + (s.e24 * x.e34)) + (s.e35 * x.e25)) - (s.e1245 * x.e1345))) + (((((0.0 - (s.e13 * x.e12)) - (s.e34 * x.e24)) - (s.e45 * x.e2345)) + (s.e1345 * x.e1245)) + ((((0.0 - (s.e23 * x.scalar)) - (s.e15 * x.e1235)) - (s.e1234 * x.e14)) + (s.e2345 * x.e45)));
    const double t4 = (((((0.0 + (s.scalar * x.e14)) - (s.e14 * x.scalar)) + (s.e25 * x.e1245)) - (s.e1235 * x.e2345)) + ((((0.0 - (s.e12 * x.e24)) + (s.e24 * x.e12)) + (s.e35 * x.e1345)) - (s.e1245 * x.e25))) + (((((0.0 - (s.e13 * x.e34)) + (s.e34 * x.e13)) + (s.e45 * x.e15)) - (s.e1345 * x.e35)) + ((((0.0 + (s.e23 * x.e1234)) - (s.e15 * x.e45)) - (s.e1234 * x.e23)) + (s.e2345 * x.e1235)));
    const double t5 = (((((0.0 + (s.scalar * x.e24)) - (s.e14 * x.e12)) - (s.e25 * x.e45)) + (s.e1235 * x.e1345)) + ((((0.0 + (s.e12 * x.e14)) - (s.e24 * x.scalar)) + (s.e35 * x.e2345)) + (s.e1245 * x.e15))) + (((((0.0 - (s.e13 * x.e1234)) + (s.e34 * x.e23)) + (s.e45 * x.e25)) - (s.e1345 * x.e1235)) + ((((0.0 - (s.e23 * x.e34)) - (s.e15 * x.e1245)) + (s.e1234 * x.e13)) - (s.e2345 * x.e35)));
    const double t6 = (((((0.0 + (s.scalar * x.e34)) - (s.e14 * x.e13)) - (s.e25 * x.e2345)) - (s.e1235 * x.e1245)) + ((((0.0 + (s.e12 * x.e1234)) - (s.e24 * x.e23)) - (s.e35 * x.e45)) + (s.e1245 * x.e1235))) + (((((0.0 + (s.e13 * x.e14)) - (s.e34 * x.scalar)) + (s.e45 * x.e35)) + (s.e1345 * x.e15)) + ((((0.0 + (s.e23 * x.e24)) - (s.e15 * x.e1345)) - (s.e1234 * x.e12)) + (s.e2345 * x.e25)));
    const double t7 = (((((0.0 + (s.scalar * x.e1234)) - (s.e14 * x.e23)) + (s.e25 * x.e1345)) + (s.e1235 * x.e45)) + ((((0.0 - (s.e12 * x.e34)) + (s.e24 * x.e13)) - (s.e35 * x.e1245)) - (s.e1245 * x.e35))) + (((((0.0 + (s.e13 * x.e24)) - (s.e34 * x.e12)) + (s.e45 * x.e1235)) + (s.e1345 * x.e25)) + ((((0.0 - (s.e23 * x.e14)) - (s.e15 * x.e2345)) + (s.e1234 * x.scalar)) - (s.e2345 * x.e15)));
    const double t8 = (((((0.0 + (s.scalar * x.e15)) - (s.e14 * x.e45)) + (s.e25 * x.e12)) - (s.e1235 * x.e23)) + ((((0.0 - (s.e12 * x.e25)) + (s.e24 * x.e1245)) + (s.e35 * x.e13)) - (s.e1245 * x.e24))) + (((((0.0 - (s.e13 * x.e35)) + (s.e34 * x.e1345)) + (s.e45 * x.e14)) - (s.e1345 * x.e34)) + ((((0.0 + (s.e23 * x.e1235)) - (s.e15 * x.scalar)) - (s.e1234 * x.e2345)) + (s.e2345 * x.e1234)));
    const double t9 = (((((0.0 + (s.scalar * x.e25)) - (s.e14 * x.e1245)) - (s.e25 * x.scalar)) + (s.e1235 * x.e13)) + ((((0.0 + (s.e12 * x.e15)) - (s.e24 * x.e45)) + (s.e35 * x.e23)) + (s.e1245 * x.e14))) + (((((0.0 - (s.e13 * x.e1235)) + (s.e34 * x.e2345)) + (s.e45 * x.e24)) - (s.e1345 * x.e1234)) + ((((0.0 - (s.e23 * x.e35)) - (s.e15 * x.e12)) + (s.e1234 * x.e1345)) - (s.e2345 * x.e34)));
    const double t10 = (((((0.0 + (s.scalar * x.e35)) - (s.e14 * x.e1345)) - (s.e25 * x.e23)) - (s.e1235 * x.e12)) + ((((0.0 + (s.e12 * x.e1235)) - (s.e24 * x.e2345)) - (s.e35 * x.scalar)) + (s.e1245 * x.e1234))) + (((((0.0 + (s.e13 * x.e15)) - (s.e34 * x.e45)) + (s.e45 * x.e34)) + (s.e1345 * x.e14)) + ((((0.0 + (s.e23 * x.e25)) - (s.e15 * x.e13)) - (s.e1234 * x.e1245)) + (s.e2345 * x.e24)));
    const double t11 = (((((0.0 + (s.scalar * x.e1235)) - (s.e14 * x.e2345)) + (s.e25 * x.e13)) + (s.e1235 * x.scalar)) + ((((0.0 - (s.e12 * x.e35)) + (s.e24 * x.e1345)) - (s.e35 * x.e12)) - (s.e1245 * x.e34))) + (((((0.0 + (s.e13 * x.e25)) - (s.e34 * x.e1245)) + (s.e45 * x.e1234)) + (s.e1345 * x.e24)) + ((((0.0 - (s.e23 * x.e15)) - (s.e15 * x.e23)) + (s.e1234 * x.e45)) - (s.e2345 * x.e14)));
    const double t12 = (((((0.0 + (s.scalar * x.e45)) + (s.e14 * x.e15)) - (s.e25 * x.e24)) - (s.e1235 * x.e1234)) + ((((0.0 + (s.e12 * x.e1245)) + (s.e24 * x.e25)) - (s.e35 * x.e34)) - (s.e1245 * x.e12))) + (((((0.0 + (s.e13 * x.e1345)) + (s.e34 * x.e35)) - (s.e45 * x.scalar)) - (s.e1345 * x.e13)) + ((((0.0 + (s.e23 * x.e2345)) - (s.e15 * x.e14)) + (s.e1234 * x.e1235)) - (s.e2345 * x.e23)));
    const double t13 = (((((0.0 + (s.scalar * x.e1245)) + (s.e14 * x.e25)) + (s.e25 * x.e14)) + (s.e1235 * x.e34)) + ((((0.0 - (s.e12 * x.e45)) - (s.e24 * x.e15)) - (s.e35 * x.e1234)) + (s.e1245 * x.scalar))) + (((((0.0 + (s.e13 * x.e2345)) + (s.e34 * x.e1235)) - (s.e45 * x.e12)) - (s.e1345 * x.e23)) + ((((0.0 - (s.e23 * x.e1345)) - (s.e15 * x.e24)) - (s.e1234 * x.e35)) + (s.e2345 * x.e13)));
    const double t14 = (((((0.0 + (s.scalar * x.e1345)) + (s.e14 * x.e35)) + (s.e25 * x.e1234)) - (s.e1235 * x.e24)) + ((((0.0 - (s.e12 * x.e2345)) - (s.e24 * x.e1235)) + (s.e35 * x.e14)) + (s.e1245 * x.e23))) + (((((0.0 - (s.e13 * x.e45)) - (s.e34 * x.e15)) - (s.e45 * x.e13)) + (s.e1345 * x.scalar)) + ((((0.0 + (s.e23 * x.e1245)) - (s.e15 * x.e34)) + (s.e1234 * x.e25)) - (s.e2345 * x.e12)));
    const double t15 = (((((0.0 + (s.scalar * x.e2345)) + (s.e14 * x.e1235)) - (s.e25 * x.e34)) + (s.e1235 * x.e14)) + ((((0.0 + (s.e12 * x.e1345)) + (s.e24 * x.e35)) + (s.e35 * x.e24)) - (s.e1245 * x.e13))) + (((((0.0 - (s.e13 * x.e1245)) - (s.e34 * x.e25)) - (s.e45 * x.e23)) + (s.e1345 * x.e12)) + ((((0.0 - (s.e23 * x.e45)) - (s.e15 * x.e1234)) - (s.e1234 * x.e15)) + (s.e2345 * x.scalar)));
    cga_Motor r;
    r.scalar = (((((0.0 + (t0 * s.scalar)) - (t4 * s.e14)) + (t8 * s.e15)) + (t12 * s.e45)) + ((((0.0 - (t1 * s.e12)) - (t5 * s.e24)) + (t9 * s.e25)) - (t13 * s.e1245))) + (((((0.0 - (t2 * s.e13)) - (t6 * s.e34)) + (t10 * s.e35)) - (t14 * s.e1345)) + ((((0.0 - (t3 * s.e23)) + (t7 * s.e1234)) - (t11 * s.e1235)) - (t15 * s.e2345)));
    r.e12 = (((((0.0 + (t0 * s.e12)) - (t4 * s.e24)) + (t8 * s.e25)) + (t12 * s.e1245)) + ((((0.0 + (t1 * s.scalar)) + (t5 * s.e14)) - (t9 * s.e15)) + (t13 * s.e45))) + (((((0.0 - (t2 * s.e23)) - (t6 * s.e1234)) + (t10 * s.e1235)) - (t14 * s.e2345)) + ((((0.0 + (t3 * s.e13)) - (t7 * s.e34)) + (t11 * s.e35)) + (t15 * s.e1345)));
    r.e13 = (((((0.0 + (t0 * s.e13)) - (t4 * s.e34)) + (t8 * s.e35)) + (t12 * s.e1345)) + ((((0.0 + (t1 * s.e23)) + (t5 * s.e1234)) - (t9 * s.e1235)) + (t13 * s.e2345))) + (((((0.0 + (t2 * s.scalar)) + (t6 * s.e14)) - (t10 * s.e15)) + (t14 * s.e45)) + ((((0.0 - (t3 * s.e12)) + (t7 * s.e24)) - (t11 * s.e25)) - (t15 * s.e1245)));
    r.e23 = (((((0.0 + (t0 * s.e23)) - (t4 * s.e1234)) + (t8 * s.e1235)) + (t12 * s.e2345)) + ((((0.0 - (t1 * s.e13)) - (t5 * s.e34)) + (t9 * s.e35)) - (t13 * s.e1345))) + (((((0.0 + (t2 * s.e12)) + (t6 * s.e24)) - (t10 * s.e25)) + (t14 * s.e1245)) + ((((0.0 + (t3 * s.scalar)) - (t7 * s.e14)) + (t11 * s.e15)) + (t15 * s.e45)));
    r.e14 = (((((0.0 + (t0 * s.e14)) + (t4 * s.scalar)) + (t8 * s.e45)) - (t12 * s.e15)) + ((((0.0 + (t1 * s.e24)) - (t5 * s.e12)) - (t9 * s.e1245)) - (t13 * s.e25))) + (((((0.0 + (t2 * s.e34)) - (t6 * s.e13)) - (t10 * s.e1345)) - (t14 * s.e35)) + ((((0.0 - (t3 * s.e1234)) - (t7 * s.e23)) - (t11 * s.e2345)) + (t15 * s.e1235)));
    r.e24 = (((((0.0 + (t0 * s.e24)) + (t4 * s.e12)) + (t8 * s.e1245)) - (t12 * s.e25)) + ((((0.0 - (t1 * s.e14)) + (t5 * s.scalar)) + (t9 * s.e45)) + (t13 * s.e15))) + (((((0.0 + (t2 * s.e1234)) - (t6 * s.e23)) - (t10 * s.e2345)) - (t14 * s.e1235)) + ((((0.0 + (t3 * s.e34)) + (t7 * s.e13)) + (t11 * s.e1345)) - (t15 * s.e35)));
    r.e34 = (((((0.0 + (t0 * s.e34)) + (t4 * s.e13)) + (t8 * s.e1345)) - (t12 * s.e35)) + ((((0.0 - (t1 * s.e1234)) + (t5 * s.e23)) + (t9 * s.e2345)) + (t13 * s.e1235))) + (((((0.0 - (t2 * s.e14)) + (t6 * s.scalar)) + (t10 * s.e45)) + (t14 * s.e15)) + ((((0.0 - (t3 * s.e24)) - (t7 * s.e12)) - (t11 * s.e1245)) + (t15 * s.e25)));
    r.e15 = (((((0.0 + (t0 * s.e15)) + (t4 * s.e45)) + (t8 * s.scalar)) - (t12 * s.e14)) + ((((0.0 + (t1 * s.e25)) - (t5 * s.e1245)) - (t9 * s.e12)) - (t13 * s.e24))) + (((((0.0 + (t2 * s.e35)) - (t6 * s.e1345)) - (t10 * s.e13)) - (t14 * s.e34)) + ((((0.0 - (t3 * s.e1235)) - (t7 * s.e2345)) - (t11 * s.e23)) + (t15 * s.e1234)));
    r.e25 = (((((0.0 + (t0 * s.e25)) + (t4 * s.e1245)) + (t8 * s.e12)) - (t12 * s.e24)) + ((((0.0 - (t1 * s.e15)) + (t5 * s.e45)) + (t9 * s.scalar)) + (t13 * s.e14))) + (((((0.0 + (t2 * s.e1235)) - (t6 * s.e2345)) - (t10 * s.e23)) - (t14 * s.e1234)) + ((((0.0 + (t3 * s.e35)) + (t7 * s.e1345)) + (t11 * s.e13)) - (t15 * s.e34)));
    r.e35 = (((((0.0 + (t0 * s.e35)) + (t4 * s.e1345)) + (t8 * s.e13)) - (t12 * s.e34)) + ((((0.0 - (t1 * s.e1235)) + (t5 * s.e2345)) + (t9 * s.e23)) + (t13 * s.e1234))) + (((((0.0 - (t2 * s.e15)) + (t6 * s.e45)) + (t10 * s.scalar)) + (t14 * s.e14)) + ((((0.0 - (t3 * s.e25)) - (t7 * s.e1245)) - (t11 * s.e12)) + (t15 * s.e24)));
    r.e45 = (((((0.0 + (t0 * s.e45)) - (t4 * s.e15)) + (t8 * s.e14)) + (t12 * s.scalar)) + ((((0.0 - (t1 * s.e1245)) - (t5 * s.e25)) + (t9 * s.e24)) - (t13 * s.e12))) + (((((0.0 - (t2 * s.e1345)) - (t6 * s.e35)) + (t10 * s.e34)) - (t14 * s.e13)) + ((((0.0 - (t3 * s.e2345)) + (t7 * s.e1235)) - (t11 * s.e1234)) - (t15 * s.e23)));
    r.e1234 = (((((0.0 + (t0 * s.e1234)) + (t4 * s.e23)) + (t8 * s.e2345)) - (t12 * s.e1235)) + ((((0.0 + (t1 * s.e34)) - (t5 * s.e13)) - (t9 * s.e1345)) - (t13 * s.e35))) + (((((0.0 - (t2 * s.e24)) + (t6 * s.e12)) + (t10 * s.e1245)) + (t14 * s.e25)) + ((((0.0 + (t3 * s.e14)) + (t7 * s.scalar)) + (t11 * s.e45)) - (t15 * s.e15)));
    r.e1235 = (((((0.0 + (t0 * s.e1235)) + (t4 * s.e2345)) + (t8 * s.e23)) - (t12 * s.e1234)) + ((((0.0 + (t1 * s.e35)) - (t5 * s.e1345)) - (t9 * s.e13)) - (t13 * s.e34))) + (((((0.0 - (t2 * s.e25)) + (t6 * s.e1245)) + (t10 * s.e12)) + (t14 * s.e24)) + ((((0.0 + (t3 * s.e15)) + (t7 * s.e45)) + (t11 * s.scalar)) - (t15 * s.e14)));
    r.e1245 = (((((0.0 + (t0 * s.e1245)) - (t4 * s.e25)) + (t8 * s.e24)) + (t12 * s.e12)) + ((((0.0 + (t1 * s.e45)) + (t5 * s.e15)) - (t9 * s.e14)) + (t13 * s.scalar))) + (((((0.0 - (t2 * s.e2345)) - (t6 * s.e1235)) + (t10 * s.e1234)) - (t14 * s.e23)) + ((((0.0 + (t3 * s.e1345)) - (t7 * s.e35)) + (t11 * s.e34)) + (t15 * s.e13)));
    r.e1345 = (((((0.0 + (t0 * s.e1345)) - (t4 * s.e35)) + (t8 * s.e34)) + (t12 * s.e13)) + ((((0.0 + (t1 * s.e2345)) + (t5 * s.e1235)) - (t9 * s.e1234)) + (t13 * s.e23))) + (((((0.0 + (t2 * s.e45)) + (t6 * s.e15)) - (t10 * s.e14)) + (t14 * s.scalar)) + ((((0.0 - (t3 * s.e1245)) + (t7 * s.e25)) - (t11 * s.e24)) - (t15 * s.e12)));
    r.e2345 = (((((0.0 + (t0 * s.e2345)) - (t4 * s.e1235)) + (t8 * s.e1234)) + (t12 * s.e23)) + ((((0.0 - (t1 * s.e1345)) - (t5 * s.e35)) + (t9 * s.e34)) - (t13 * s.e13))) + (((((0.0 + (t2 * s.e1245)) + (t6 * s.e25)) - (t10 * s.e24)) + (t14 * s.e12)) + ((((0.0 + (t3 * s.e45)) - (t7 * s.e15)) + (t11 * s.e14)) + (t15 * s.scalar)));
    return r;
}

/* rev(S) x S for a unit Motor S (S rev(S) = 1) and a Vector x; not the action otherwise. */
static inline cga_Vector cga_motor_sandwich_unit_vector(cga_Motor s, cga_Vector x) {
    const double t0 = -(((s.e12 * x.e2) + (s.e13 * x.e3)) + ((s.e14 * x.e4) - (s.e15 * x.e5)));
    const double t1 = ((s.e12 * x.e1) - (s.e23 * x.e3)) - ((s.e24 * x.e4) - (s.e25 * x.e5));
    const double t2 = ((s.e13 * x.e1) + (s.e23 * x.e2)) - ((s.e34 * x.e4) - (s.e35 * x.e5));
    const double t3 = (s.e1234 * x.e4) - (s.e1235 * x.e5);
    const double t4 = ((s.e14 * x.e1) + (s.e24 * x.e2)) + ((s.e34 * x.e3) + (s.e45 * x.e5));
    const double t5 = -((s.e1234 * x.e3) + (s.e1245 * x.e5));
    const double t6 = (s.e1234 * x.e2) - (s.e1345 * x.e5);
    const double t7 = -((s.e1234 * x.e1) + (s.e2345 * x.e5));
    const double t8 = ((s.e15 * x.e1) + (s.e25 * x.e2)) + ((s.e35 * x.e3) + (s.e45 * x.e4));
    const double t9 = -((s.e1235 * x.e3) + (s.e1245 * x.e4));
    const double t10 = (s.e1235 * x.e2) - (s.e1345 * x.e4);
    const double t11 = -((s.e1235 * x.e1) + (s.e2345 * x.e4));
    const double t12 = (s.e1245 * x.e2) + (s.e1345 * x.e3);
    const double t13 = -((s.e1245 * x.e1) - (s.e2345 * x.e3));
    const double t14 = -((s.e1345 * x.e1) + (s.e2345 * x.e2));
    const double t15 = (((t0 * s.scalar) - ((t1 * s.e12) + (t2 * s.e13))) - (((t3 * s.e23) + (t4 * s.e14)) + ((t5 * s.e24) + (t6 * s.e34)))) + ((((t7 * s.e1234) + (t8 * s.e15)) + ((t9 * s.e25) + (t10 * s.e35))) - (((t11 * s.e1235) - (t12 * s.e45)) + ((t13 * s.e1245) + (t14 * s.e1345))));
    const double t16 = (((t0 * s.e12) + ((t1 * s.scalar) - (t2 * s.e23))) + (((t3 * s.e13) - (t4 * s.e24)) + ((t5 * s.e14) - (t6 * s.e1234)))) - ((((t7 * s.e34) - (t8 * s.e25)) + ((t9 * s.e15) - (t10 * s.e1235))) - (((t11 * s.e35) + (t12 * s.e1245)) + ((t13 * s.e45) - (t14 * s.e2345))));
    const double t17 = (((t0 * s.e13) + ((t1 * s.e23) + (t2 * s.scalar))) - (((t3 * s.e12) + (t4 * s.e34)) - ((t5 * s.e1234) + (t6 * s.e14)))) + ((((t7 * s.e24) + (t8 * s.e35)) - ((t9 * s.e1235) + (t10 * s.e15))) - (((t11 * s.e25) - (t12 * s.e1345)) - ((t13 * s.e2345) + (t14 * s.e45))));
    const double t18 = (((t0 * s.e14) + ((t1 * s.e24) + (t2 * s.e34))) - (((t3 * s.e1234) - (t4 * s.scalar)) + ((t5 * s.e12) + (t6 * s.e13)))) - ((((t7 * s.e23) - (t8 * s.e45)) + ((t9 * s.e1245) + (t10 * s.e1345))) + (((t11 * s.e2345) + (t12 * s.e15)) + ((t13 * s.e25) + (t14 * s.e35))));
    const double t19 = (((t0 * s.e15) + ((t1 * s.e25) + (t2 * s.e35))) - (((t3 * s.e1235) - (t4 * s.e45)) + ((t5 * s.e1245) + (t6 * s.e1345)))) - ((((t7 * s.e2345) - (t8 * s.scalar)) + ((t9 * s.e12) + (t10 * s.e13))) + (((t11 * s.e23) + (t12 * s.e14)) + ((t13 * s.e24) + (t14 * s.e34))));
    cga_Vector r;
    r.e1 = (x.e1 + t15) + t15;
    r.e2 = (x.e2 + t16) + t16;
    r.e3 = (x.e3 + t17) + t17;
    r.e4 = (x.e4 + t18) + t18;
    r.e5 = (x.e5 + t19) + t19;
    return r;
}

/* rev(S) x S for a unit Vector S (S rev(S) = 1) and a Motor x; not the action otherwise. */
static inline cga_Motor cga_vector_sandwich_unit_motor(cga_Vector s, cga_Motor x) {
    const double t0 = -(((s.e2 * x.e12) + (s.e3 * x.e13)) + ((s.e4 * x.e14) - (s.e5 * x.e15)));
    const double t1 = ((s.e1 * x.e12) - (s.e3 * x.e23)) - ((s.e4 * x.e24) - (s.e5 * x.e25));
    const double t2 = ((s.e1 * x.e13) + (s.e2 * x.e23)) - ((s.e4 * x.e34) - (s.e5 * x.e35));
    const double t3 = -((s.e4 * x.e1234) - (s.e5 * x.e1235));
    const double t4 = ((s.e1 * x.e14) + (s.e2 * x.e24)) + ((s.e3 * x.e34) + (s.e5 * x.e45));
    const double t5 = (s.e3 * x.e1234) + (s.e5 * x.e1245);
    const double t6 = -((s.e2 * x.e1234) - (s.e5 * x.e1345));
    const double t7 = (s.e1 * x.e1234) + (s.e5 * x.e2345);
    const double t8 = ((s.e1 * x.e15) + (s.e2 * x.e25)) + ((s.e3 * x.e35) + (s.e4 * x.e45));
    const double t9 = (s.e3 * x.e1235) + (s.e4 * x.e1245);
    const double t10 = -((s.e2 * x.e1235) - (s.e4 * x.e1345));
    const double t11 = (s.e1 * x.e1235) + (s.e4 * x.e2345);
    const double t12 = -((s.e2 * x.e1245) + (s.e3 * x.e1345));
    const double t13 = (s.e1 * x.e1245) - (s.e3 * x.e2345);
    const double t14 = (s.e1 * x.e1345) + (s.e2 * x.e2345);
    const double t15 = ((t0 * s.e2) - (t1 * s.e1)) + ((t3 * s.e3) + ((t5 * s.e4) - (t9 * s.e5)));
    const double t16 = ((t0 * s.e3) - (t2 * s.e1)) - ((t3 * s.e2) - ((t6 * s.e4) - (t10 * s.e5)));
    const double t17 = ((t1 * s.e3) - (t2 * s.e2)) + ((t3 * s.e1) + ((t7 * s.e4) - (t11 * s.e5)));
    const double t18 = ((t0 * s.e4) - (t4 * s.e1)) - ((t5 * s.e2) + ((t6 * s.e3) + (t12 * s.e5)));
    const double t19 = ((t1 * s.e4) - (t4 * s.e2)) + ((t5 * s.e1) - ((t7 * s.e3) + (t13 * s.e5)));
    const double t20 = ((t2 * s.e4) - (t4 * s.e3)) + ((t6 * s.e1) + ((t7 * s.e2) - (t14 * s.e5)));
    const double t21 = ((t0 * s.e5) - (t8 * s.e1)) - ((t9 * s.e2) + ((t10 * s.e3) + (t12 * s.e4)));
    const double t22 = ((t1 * s.e5) - (t8 * s.e2)) + ((t9 * s.e1) - ((t11 * s.e3) + (t13 * s.e4)));
    const double t23 = ((t2 * s.e5) - (t8 * s.e3)) + ((t10 * s.e1) + ((t11 * s.e2) - (t14 * s.e4)));
    const double t24 = ((t4 * s.e5) - (t8 * s.e4)) + ((t12 * s.e1) + ((t13 * s.e2) + (t14 * s.e3)));
    const double t25 = ((t3 * s.e4) - (t5 * s.e3)) + ((t6 * s.e2) - (t7 * s.e1));
    const double t26 = ((t3 * s.e5) - (t9 * s.e3)) + ((t10 * s.e2) - (t11 * s.e1));
    const double t27 = ((t5 * s.e5) - (t9 * s.e4)) + ((t12 * s.e2) - (t13 * s.e1));
    const double t28 = ((t6 * s.e5) - (t10 * s.e4)) + ((t12 * s.e3) - (t14 * s.e1));
    const double t29 = ((t7 * s.e5) - (t11 * s.e4)) + ((t13 * s.e3) - (t14 * s.e2));
    cga_Motor r;
    r.scalar = x.scalar;
    r.e12 = (x.e12 + t15) + t15;
    r.e13 = (x.e13 + t16) + t16;
    r.e23 = (x.e23 + t17) + t17;
    r.e14 = (x.e14 + t18) + t18;
    r.e24 = (x.e24 + t19) + t19;
    r.e34 = (x.e34 + t20) + t20;
    r.e15 = (x.e15 + t21) + t21;
    r.e25 = (x.e25 + t22) + t22;
    r.e35 = (x.e35 + t23) + t23;
    r.e45 = (x.e45 + t24) + t24;
    r.e1234 = (x.e1234 + t25) + t25;
    r.e1235 = (x.e1235 + t26) + t26;
    r.e1245 = (x.e1245 + t27) + t27;
    r.e1345 = (x.e1345 + t28) + t28;
    r.e2345 = (x.e2345 + t29) + t29;
    return r;
}

/* rev(S) x S for a unit Vector S (S rev(S) = 1) and a Vector x; not the action otherwise. */
static inline cga_Vector cga_vector_sandwich_unit_vector(cga_Vector s, cga_Vector x) {
    const double t0 = (s.e1 * x.e2) - (s.e2 * x.e1);
    const double t1 = (s.e1 * x.e3) - (s.e3 * x.e1);
    const double t2 = (s.e2 * x.e3) - (s.e3 * x.e2);
    const double t3 = (s.e1 * x.e4) - (s.e4 * x.e1);
    const double t4 = (s.e2 * x.e4) - (s.e4 * x.e2);
    const double t5 = (s.e3 * x.e4) - (s.e4 * x.e3);
    const double t6 = (s.e1 * x.e5) - (s.e5 * x.e1);
    const double t7 = (s.e2 * x.e5) - (s.e5 * x.e2);
    const double t8 = (s.e3 * x.e5) - (s.e5 * x.e3);
    const double t9 = (s.e4 * x.e5) - (s.e5 * x.e4);
    const double t10 = ((t0 * s.e2) + (t1 * s.e3)) + ((t3 * s.e4) - (t6 * s.e5));
    const double t11 = -(((t0 * s.e1) - (t2 * s.e3)) - ((t4 * s.e4) - (t7 * s.e5)));
    const double t12 = -(((t1 * s.e1) + (t2 * s.e2)) - ((t5 * s.e4) - (t8 * s.e5)));
    const double t13 = -(((t3 * s.e1) + (t4 * s.e2)) + ((t5 * s.e3) + (t9 * s.e5)));
    const double t14 = -(((t6 * s.e1) + (t7 * s.e2)) + ((t8 * s.e3) + (t9 * s.e4)));
    cga_Vector r;
    r.e1 = (x.e1 + t10) + t10;
    r.e2 = (x.e2 + t11) + t11;
    r.e3 = (x.e3 + t12) + t12;
    r.e4 = (x.e4 + t13) + t13;
    r.e5 = (x.e5 + t14) + t14;
    return r;
}

/* Motor: the coefficients of scalar, e12, e13, e23, e14, e24, e34, e15, e25, e35, e45, e1234, e1235, e1245, e1345, e2345. */
typedef struct cga_Motorf {
    float scalar;
    float e12;
    float e13;
    float e23;
    float e14;
    float e24;
    float e34;
    float e15;
    float e25;
    float e35;
    float e45;
    float e1234;
    float e1235;
    float e1245;
    float e1345;
    float e2345;
} cga_Motorf;

/* Vector: the coefficients of e1, e2, e3, e4, e5. */
typedef struct cga_Vectorf {
    float e1;
    float e2;
    float e3;
    float e4;
    float e5;
} cga_Vectorf;

/* The reverse of a Motor. */
static inline cga_Motorf cga_motor_reversef(cga_Motorf x) {
    cga_Motorf r;
    r.scalar = x.scalar;
    r.e12 = -x.e12;
    r.e13 = -x.e13;
    r.e23 = -x.e23;
    r.e14 = -x.e14;
    r.e24 = -x.e24;
    r.e34 = -x.e34;
    r.e15 = -x.e15;
    r.e25 = -x.e25;
    r.e35 = -x.e35;
    r.e45 = -x.e45;
    r.e1234 = x.e1234;
    r.e1235 = x.e1235;
    r.e1245 = x.e1245;
    r.e1345 = x.e1345;
    r.e2345 = x.e2345;
    return r;
}

/* The squared norm <x rev(x)>_0 of a Motor (may be negative or zero). */
static inline float cga_motor_norm_squaredf(cga_Motorf x) {
    const float t0 = x.scalar * x.scalar;
    const float t1 = x.e12 * x.e12;
    const float t2 = x.e13 * x.e13;
    const float t3 = x.e23 * x.e23;
    const float t4 = x.e14 * x.e14;
    const float t5 = x.e24 * x.e24;
    const float t6 = x.e34 * x.e34;
    const float t7 = x.e15 * x.e15;
    const float t8 = x.e25 * x.e25;
    const float t9 = x.e35 * x.e35;
    const float t10 = x.e45 * x.e45;
    const float t11 = x.e1234 * x.e1234;
    const float t12 = x.e1235 * x.e1235;
    const float t13 = x.e1245 * x.e1245;
    const float t14 = x.e1345 * x.e1345;
    const float t15 = x.e2345 * x.e2345;
    return ((((((((((((((t0 + t1) + t2) + t3) + t4) + t5) + t6) - t7) - t8) - t9) - t10) + t11) - t12) - t13) - t14) - t15;
}

/* The reverse of a Vector. */
static inline cga_Vectorf cga_vector_reversef(cga_Vectorf x) {
    cga_Vectorf r;
    r.e1 = x.e1;
    r.e2 = x.e2;
    r.e3 = x.e3;
    r.e4 = x.e4;
    r.e5 = x.e5;
    return r;
}

/* The squared norm <x rev(x)>_0 of a Vector (may be negative or zero). */
static inline float cga_vector_norm_squaredf(cga_Vectorf x) {
    const float t0 = x.e1 * x.e1;
    const float t1 = x.e2 * x.e2;
    const float t2 = x.e3 * x.e3;
    const float t3 = x.e4 * x.e4;
    const float t4 = x.e5 * x.e5;
    return (((t0 + t1) + t2) + t3) - t4;
}

/* rev(S) x S for a Motor S and a Motor x, in one fused kernel. (the general action: this pair is above the size threshold) */
static inline cga_Motorf cga_motor_sandwich_unit_motorf(cga_Motorf s, cga_Motorf x) {
    const float t0 = (((((0.0f + (s.scalar * x.scalar)) + (s.e14 * x.e14)) - (s.e25 * x.e25)) - (s.e1235 * x.e1235)) + ((((0.0f + (s.e12 * x.e12)) + (s.e24 * x.e24)) - (s.e35 * x.e35)) - (s.e1245 * x.e1245))) + (((((0.0f + (s.e13 * x.e13)) + (s.e34 * x.e34)) - (s.e45 * x.e45)) - (s.e1345 * x.e1345)) + ((((0.0f + (s.e23 * x.e23)) - (s.e15 * x.e15)) + (s.e1234 * x.e1234)) - (s.e2345 * x.e2345)));
    const float t1 = (((((0.0f + (s.scalar * x.e12)) + (s.e14 * x.e24)) + (s.e25 * x.e15)) + (s.e1235 * x.e35)) + ((((0.0f - (s.e12 * x.scalar)) - (s.e24 * x.e14)) - (s.e35 * x.e1235)) + (s.e1245 * x.e45))) + (((((0.0f + (s.e13 * x.e23)) + (s.e34 * x.e1234)) - (s.e45 * x.e1245)) - (s.e1345 * x.e2345)) + ((((0.0f - (s.e23 * x.e13)) - (s.e15 * x.e25)) - (s.e1234 * x.e34)) + (s.e2345 * x.e1345)));
    const float t2 = (((((0.0f + (s.scalar * x.e13)) + (s.e14 * x.e34)) + (s.e25 * x.e1235)) - (s.e1235 * x.e25)) + ((((0.0f - (s.e12 * x.e23)) - (s.e24 * x.e1234)) + (s.e35 * x.e15)) + (s.e1245 * x.e2345))) + (((((0.0f - (s.e13 * x.scalar)) - (s.e34 * x.e14)) - (s.e45 * x.e1345)) + (s.e1345 * x.e45)) + ((((0.0f + (s.e23 * x.e12)) - (s.e15 * x.e35)) + (s.e1234 * x.e24)) - (s.e2345 * x.e1245)));
    const float t3 = (((((0.0f + (s.scalar * x.e23)) + (s.e14 * x.e1234)) - (s.e25 * x.e35)) + (s.e1235 * x.e15)) + ((((0.0f + (s.e12 * x.e13)) + (s.e24 * x.e34)) + (s.e35 * x.e25)) - (s.e1245 * x.e1345))) + (((((0.0f - (s.e13 * x.e12)) - (s.e34 * x.e24)) - (s.e45 * x.e2345)) + (s.e1345 * x.e1245)) + ((((0.0f - (s.e23 * x.scalar)) - (s.e15 * x.e1235)) - (s.e1234 * x.e14)) + (s.e2345 * x.e45)));
    const float t4 = (((((0.0f + (s.scalar * x.e14)) - (s.e14 * x.scalar)) + (s.e25 * x.e1245)) - (s.e1235 * x.e2345)) + ((((0.0f - (s.e12 * x.e24)) + (s.e24 * x.e12)) + (s.e35 * x.e1345)) - (s.e1245 * x.e25))) + (((((0.0f - (s.e13 * x.e34)) + (s.e34 * x.e13)) + (s.e45 * x.e15)) - (s.e1345 * x.e35)) + ((((0.0f + (s.e23 * x.e1234)) - (s.e15 * x.e45)) - (s.e1234 * x.e23)) + (s.e2345 * x.e1235)));
    const float t5 = (((((0.0f + (s.scalar * x.e24)) - (s.e14 * x.e12)) - (s.e25 * x.e45)) + (s.e1235 * x.e1345)) + ((((0.0f + (s.e12 * x.e14)) - (s.e24 * x.scalar)) + (s.e35 * x.e2345)) + (s.e1245 * x.e15))) + (((((0.0f - (s.e13 * x.e1234)) + (s.e34 * x.e23)) + (s.e45 * x.e25)) - (s.e1345 * x.e1235)) + ((((0.0f - (s.e23 * x.e34)) - (s.e15 * x.e1245)) + (s.e1234 * x.e13)) - (s.e2345 * x.e35)));
    const float t6 = (((((0.0f + (s.scalar * x.e34)) - (s.e14 * x.e13)) - (s.e25 * x.e2345)) - (s.e1235 * x.e1245)) + ((((0.0f + (s.e12 * x.e1234)) - (s.e24 * x.e23)) - (s.e35 * x.e45)) + (s.e1245 * x.e1235))) + (((((0.0f + (s.e13 * x.e14)) - (s.e34 * x.scalar)) + (s.e45 * x.e35)) + (s.e1345 * x.e15)) + ((((0.0f + (s.e23 * x.e24)) - (s.e15 * x.e1345)) - (s.e1234 * x.e12)) + (s.e2345 * x.e25)));
    const float t7 = (((((0.0f + (s.scalar * x.e1234)) - (s.e14 * x.e23)) + (s.e25 * x.e1345)) + (s.e1235 * x.e45)) + ((((0.0f - (s.e12 * x.e34)) + (s.e24 * x.e13)) - (s.e35 * x.e1245)) - (s.e1245 * x.e35))) + (((((0.0f + (s.e13 * x.e24)) - (s.e34 * x.e12)) + (s.e45 * x.e1235)) + (s.e1345 * x.e25)) + ((((0.0f - (s.e23 * x.e14)) - (s.e15 * x.e2345)) + (s.e1234 * x.scalar)) - (s.e2345 * x.e15)));
    const float t8 = (((((0.0f + (s.scalar * x.e15)) - (s.e14 * x.e45)) + (s.e25 * x.e12)) - (s.e1235 * x.e23)) + ((((0.0f - (s.e12 * x.e25)) + (s.e24 * x.e1245)) + (s.e35 * x.e13)) - (s.e1245 * x.e24))) + (((((0.0f - (s.e13 * x.e35)) + (s.e34 * x.e1345)) + (s.e45 * x.e14)) - (s.e1345 * x.e34)) + ((((0.0f + (s.e23 * x.e1235)) - (s.e15 * x.scalar)) - (s.e1234 * x.e2345)) + (s.e2345 * x.e1234)));
    const float t9 = (((((0.0f + (s.scalar * x.e25)) - (s.e14 * x.e1245)) - (s.e25 * x.scalar)) + (s.e1235 * x.e13)) + ((((0.0f + (s.e12 * x.e15)) - (s.e24 * x.e45)) + (s.e35 * x.e23)) + (s.e1245 * x.e14))) + (((((0.0f - (s.e13 * x.e1235)) + (s.e34 * x.e2345)) + (s.e45 * x.e24)) - (s.e1345 * x.e1234)) + ((((0.0f - (s.e23 * x.e35)) - (s.e15 * x.e12)) + (s.e1234 * x.e1345)) - (s.e2345 * x.e34)));
    const float t10 = (((((0.0f + (s.scalar * x.e35)) - (s.e14 * x.e1345)) - (s.e25 * x.e23)) - (s.e1235 * x.e12)) + ((((0.0f + (s.e12 * x.e1235)) - (s.e24 * x.e2345)) - (s.e35 * x.scalar)) + (s.e1245 * x.e1234))) + (((((0.0f + (s.e13 * x.e15)) - (s.e34 * x.e45)) + (s.e45 * x.e34)) + (s.e1345 * x.e14)) + ((((0.0f + (s.e23 * x.e25)) - (s.e15 * x.e13)) - (s.e1234 * x.e1245)) + (s.e2345 * x.e24)));
    const float t11 = (((((0.0f + (s.scalar * x.e1235)) - (s.e14 * x.e2345)) + (s.e25 * x.e13)) + (s.e1235 * x.scalar)) + ((((0.0f - (s.e12 * x.e35)) + (s.e24 * x.e1345)) - (s.e35 * x.e12)) - (s.e1245 * x.e34))) + (((((0.0f + (s.e13 * x.e25)) - (s.e34 * x.e1245)) + (s.e45 * x.e1234)) + (s.e1345 * x.e24)) + ((((0.0f - (s.e23 * x.e15)) - (s.e15 * x.e23)) + (s.e1234 * x.e45)) - (s.e2345 * x.e14)));
    const float t12 = (((((0.0f + (s.scalar * x.e45)) + (s.e14 * x.e15)) - (s.e25 * x.e24)) - (s.e1235 * x.e1234)) + ((((0.0f + (s.e12 * x.e1245)) + (s.e24 * x.e25)) - (s.e35 * x.e34)) - (s.e1245 * x.e12))) + (((((0.0f + (s.e13 * x.e1345)) + (s.e34 * x.e35)) - (s.e45 * x.scalar)) - (s.e1345 * x.e13)) + ((((0.0f + (s.e23 * x.e2345)) - (s.e15 * x.e14)) + (s.e1234 * x.e1235)) - (s.e2345 * x.e23)));
    const float t13 = (((((0.0f + (s.scalar * x.e1245)) + (s.e14 * x.e25)) + (s.e25 * x.e14)) + (s.e1235 * x.e34)) + ((((0.0f - (s.e12 * x.e45)) - (s.e24 * x.e15)) - (s.e35 * x.e1234)) + (s.e1245 * x.scalar))) + (((((0.0f + (s.e13 * x.e2345)) + (s.e34 * x.e1235)) - (s.e45 * x.e12)) - (s.e1345 * x.e23)) + ((((0.0f - (s.e23 * x.e1345)) - (s.e15 * x.e24)) - (s.e1234 * x.e35)) + (s.e2345 * x.e13)));
    const float t14 = (((((0.0f + (s.scalar * x.e1345)) + (s.e14 * x.e35)) + (s.e25 * x.e1234)) - (s.e1235 * x.e24)) + ((((0.0f - (s.e12 * x.e2345)) - (s.e24 * x.e1235)) + (s.e35 * x.e14)) + (s.e1245 * x.e23))) + (((((0.0f - (s.e13 * x.e45)) - (s.e34 * x.e15)) - (s.e45 * x.e13)) + (s.e1345 * x.scalar)) + ((((0.0f + (s.e23 * x.e1245)) - (s.e15 * x.e34)) + (s.e1234 * x.e25)) - (s.e2345 * x.e12)));
    const float t15 = (((((0.0f + (s.scalar * x.e2345)) + (s.e14 * x.e1235)) - (s.e25 * x.e34)) + (s.e1235 * x.e14)) + ((((0.0f + (s.e12 * x.e1345)) + (s.e24 * x.e35)) + (s.e35 * x.e24)) - (s.e1245 * x.e13))) + (((((0.0f - (s.e13 * x.e1245)) - (s.e34 * x.e25)) - (s.e45 * x.e23)) + (s.e1345 * x.e12)) + ((((0.0f - (s.e23 * x.e45)) - (s.e15 * x.e1234)) - (s.e1234 * x.e15)) + (s.e2345 * x.scalar)));
    cga_Motorf r;
    r.scalar = (((((0.0f + (t0 * s.scalar)) - (t4 * s.e14)) + (t8 * s.e15)) + (t12 * s.e45)) + ((((0.0f - (t1 * s.e12)) - (t5 * s.e24)) + (t9 * s.e25)) - (t13 * s.e1245))) + (((((0.0f - (t2 * s.e13)) - (t6 * s.e34)) + (t10 * s.e35)) - (t14 * s.e1345)) + ((((0.0f - (t3 * s.e23)) + (t7 * s.e1234)) - (t11 * s.e1235)) - (t15 * s.e2345)));
    r.e12 = (((((0.0f + (t0 * s.e12)) - (t4 * s.e24)) + (t8 * s.e25)) + (t12 * s.e1245)) + ((((0.0f + (t1 * s.scalar)) + (t5 * s.e14)) - (t9 * s.e15)) + (t13 * s.e45))) + (((((0.0f - (t2 * s.e23)) - (t6 * s.e1234)) + (t10 * s.e1235)) - (t14 * s.e2345)) + ((((0.0f + (t3 * s.e13)) - (t7 * s.e34)) + (t11 * s.e35)) + (t15 * s.e1345)));
    r.e13 = (((((0.0f + (t0 * s.e13)) - (t4 * s.e34)) + (t8 * s.e35)) + (t12 * s.e1345)) + ((((0.0f + (t1 * s.e23)) + (t5 * s.e1234)) - (t9 * s.e1235)) + (t13 * s.e2345))) + (((((0.0f + (t2 * s.scalar)) + (t6 * s.e14)) - (t10 * s.e15)) + (t14 * s.e45)) + ((((0.0f - (t3 * s.e12)) + (t7 * s.e24)) - (t11 * s.e25)) - (t15 * s.e1245)));
    r.e23 = (((((0.0f + (t0 * s.e23)) - (t4 * s.e1234)) + (t8 * s.e1235)) + (t12 * s.e2345)) + ((((0.0f - (t1 * s.e13)) - (t5 * s.e34)) + (t9 * s.e35)) - (t13 * s.e1345))) + (((((0.0f + (t2 * s.e12)) + (t6 * s.e24)) - (t10 * s.e25)) + (t14 * s.e1245)) + ((((0.0f + (t3 * s.scalar)) - (t7 * s.e14)) + (t11 * s.e15)) + (t15 * s.e45)));
    r.e14 = (((((0.0f + (t0 * s.e14)) + (t4 * s.scalar)) + (t8 * s.e45)) - (t12 * s.e15)) + ((((0.0f + (t1 * s.e24)) - (t5 * s.e12)) - (t9 * s.e1245)) - (t13 * s.e25))) + (((((0.0f + (t2 * s.e34)) - (t6 * s.e13)) - (t10 * s.e1345)) - (t14 * s.e35)) + ((((0.0f - (t3 * s.e1234)) - (t7 * s.e23)) - (t11 * s.e2345)) + (t15 * s.e1235)));
    r.e24 = (((((0.0f + (t0 * s.e24)) + (t4 * s.e12)) + (t8 * s.e1245)) - (t12 * s.e25)) + ((((0.0f - (t1 * s.e14)) + (t5 * s.scalar)) + (t9 * s.e45)) + (t13 * s.e15))) + (((((0.0f + (t2 * s.e1234)) - (t6 * s.e23)) - (t10 * s.e2345)) - (t14 * s.e1235)) + ((((0.0f + (t3 * s.e34)) + (t7 * s.e13)) + (t11 * s.e1345)) - (t15 * s.e35)));
    r.e34 = (((((0.0f + (t0 * s.e34)) + (t4 * s.e13)) + (t8 * s.e1345)) - (t12 * s.e35)) + ((((0.0f - (t1 * s.e1234)) + (t5 * s.e23)) + (t9 * s.e2345)) + (t13 * s.e1235))) + (((((0.0f - (t2 * s.e14)) + (t6 * s.scalar)) + (t10 * s.e45)) + (t14 * s.e15)) + ((((0.0f - (t3 * s.e24)) - (t7 * s.e12)) - (t11 * s.e1245)) + (t15 * s.e25)));
    r.e15 = (((((0.0f + (t0 * s.e15)) + (t4 * s.e45)) + (t8 * s.scalar)) - (t12 * s.e14)) + ((((0.0f + (t1 * s.e25)) - (t5 * s.e1245)) - (t9 * s.e12)) - (t13 * s.e24))) + (((((0.0f + (t2 * s.e35)) - (t6 * s.e1345)) - (t10 * s.e13)) - (t14 * s.e34)) + ((((0.0f - (t3 * s.e1235)) - (t7 * s.e2345)) - (t11 * s.e23)) + (t15 * s.e1234)));
    r.e25 = (((((0.0f + (t0 * s.e25)) + (t4 * s.e1245)) + (t8 * s.e12)) - (t12 * s.e24)) + ((((0.0f - (t1 * s.e15)) + (t5 * s.e45)) + (t9 * s.scalar)) + (t13 * s.e14))) + (((((0.0f + (t2 * s.e1235)) - (t6 * s.e2345)) - (t10 * s.e23)) - (t14 * s.e1234)) + ((((0.0f + (t3 * s.e35)) + (t7 * s.e1345)) + (t11 * s.e13)) - (t15 * s.e34)));
    r.e35 = (((((0.0f + (t0 * s.e35)) + (t4 * s.e1345)) + (t8 * s.e13)) - (t12 * s.e34)) + ((((0.0f - (t1 * s.e1235)) + (t5 * s.e2345)) + (t9 * s.e23)) + (t13 * s.e1234))) + (((((0.0f - (t2 * s.e15)) + (t6 * s.e45)) + (t10 * s.scalar)) + (t14 * s.e14)) + ((((0.0f - (t3 * s.e25)) - (t7 * s.e1245)) - (t11 * s.e12)) + (t15 * s.e24)));
    r.e45 = (((((0.0f + (t0 * s.e45)) - (t4 * s.e15)) + (t8 * s.e14)) + (t12 * s.scalar)) + ((((0.0f - (t1 * s.e1245)) - (t5 * s.e25)) + (t9 * s.e24)) - (t13 * s.e12))) + (((((0.0f - (t2 * s.e1345)) - (t6 * s.e35)) + (t10 * s.e34)) - (t14 * s.e13)) + ((((0.0f - (t3 * s.e2345)) + (t7 * s.e1235)) - (t11 * s.e1234)) - (t15 * s.e23)));
    r.e1234 = (((((0.0f + (t0 * s.e1234)) + (t4 * s.e23)) + (t8 * s.e2345)) - (t12 * s.e1235)) + ((((0.0f + (t1 * s.e34)) - (t5 * s.e13)) - (t9 * s.e1345)) - (t13 * s.e35))) + (((((0.0f - (t2 * s.e24)) + (t6 * s.e12)) + (t10 * s.e1245)) + (t14 * s.e25)) + ((((0.0f + (t3 * s.e14)) + (t7 * s.scalar)) + (t11 * s.e45)) - (t15 * s.e15)));
    r.e1235 = (((((0.0f + (t0 * s.e1235)) + (t4 * s.e2345)) + (t8 * s.e23)) - (t12 * s.e1234)) + ((((0.0f + (t1 * s.e35)) - (t5 * s.e1345)) - (t9 * s.e13)) - (t13 * s.e34))) + (((((0.0f - (t2 * s.e25)) + (t6 * s.e1245)) + (t10 * s.e12)) + (t14 * s.e24)) + ((((0.0f + (t3 * s.e15)) + (t7 * s.e45)) + (t11 * s.scalar)) - (t15 * s.e14)));
    r.e1245 = (((((0.0f + (t0 * s.e1245)) - (t4 * s.e25)) + (t8 * s.e24)) + (t12 * s.e12)) + ((((0.0f + (t1 * s.e45)) + (t5 * s.e15)) - (t9 * s.e14)) + (t13 * s.scalar))) + (((((0.0f - (t2 * s.e2345)) - (t6 * s.e1235)) + (t10 * s.e1234)) - (t14 * s.e23)) + ((((0.0f + (t3 * s.e1345)) - (t7 * s.e35)) + (t11 * s.e34)) + (t15 * s.e13)));
    r.e1345 = (((((0.0f + (t0 * s.e1345)) - (t4 * s.e35)) + (t8 * s.e34)) + (t12 * s.e13)) + ((((0.0f + (t1 * s.e2345)) + (t5 * s.e1235)) - (t9 * s.e1234)) + (t13 * s.e23))) + (((((0.0f + (t2 * s.e45)) + (t6 * s.e15)) - (t10 * s.e14)) + (t14 * s.scalar)) + ((((0.0f - (t3 * s.e1245)) + (t7 * s.e25)) - (t11 * s.e24)) - (t15 * s.e12)));
    r.e2345 = (((((0.0f + (t0 * s.e2345)) - (t4 * s.e1235)) + (t8 * s.e1234)) + (t12 * s.e23)) + ((((0.0f - (t1 * s.e1345)) - (t5 * s.e35)) + (t9 * s.e34)) - (t13 * s.e13))) + (((((0.0f + (t2 * s.e1245)) + (t6 * s.e25)) - (t10 * s.e24)) + (t14 * s.e12)) + ((((0.0f + (t3 * s.e45)) - (t7 * s.e15)) + (t11 * s.e14)) + (t15 * s.scalar)));
    return r;
}

/* rev(S) x S for a unit Motor S (S rev(S) = 1) and a Vector x; not the action otherwise. */
static inline cga_Vectorf cga_motor_sandwich_unit_vectorf(cga_Motorf s, cga_Vectorf x) {
    const float t0 = -(((s.e12 * x.e2) + (s.e13 * x.e3)) + ((s.e14 * x.e4) - (s.e15 * x.e5)));
    const float t1 = ((s.e12 * x.e1) - (s.e23 * x.e3)) - ((s.e24 * x.e4) - (s.e25 * x.e5));
    const float t2 = ((s.e13 * x.e1) + (s.e23 * x.e2)) - ((s.e34 * x.e4) - (s.e35 * x.e5));
    const float t3 = (s.e1234 * x.e4) - (s.e1235 * x.e5);
    const float t4 = ((s.e14 * x.e1) + (s.e24 * x.e2)) + ((s.e34 * x.e3) + (s.e45 * x.e5));
    const float t5 = -((s.e1234 * x.e3) + (s.e1245 * x.e5));
    const float t6 = (s.e1234 * x.e2) - (s.e1345 * x.e5);
    const float t7 = -((s.e1234 * x.e1) + (s.e2345 * x.e5));
    const float t8 = ((s.e15 * x.e1) + (s.e25 * x.e2)) + ((s.e35 * x.e3) + (s.e45 * x.e4));
    const float t9 = -((s.e1235 * x.e3) + (s.e1245 * x.e4));
    const float t10 = (s.e1235 * x.e2) - (s.e1345 * x.e4);
    const float t11 = -((s.e1235 * x.e1) + (s.e2345 * x.e4));
    const float t12 = (s.e1245 * x.e2) + (s.e1345 * x.e3);
    const float t13 = -((s.e1245 * x.e1) - (s.e2345 * x.e3));
    const float t14 = -((s.e1345 * x.e1) + (s.e2345 * x.e2));
    const float t15 = (((t0 * s.scalar) - ((t1 * s.e12) + (t2 * s.e13))) - (((t3 * s.e23) + (t4 * s.e14)) + ((t5 * s.e24) + (t6 * s.e34)))) + ((((t7 * s.e1234) + (t8 * s.e15)) + ((t9 * s.e25) + (t10 * s.e35))) - (((t11 * s.e1235) - (t12 * s.e45)) + ((t13 * s.e1245) + (t14 * s.e1345))));
    const float t16 = (((t0 * s.e12) + ((t1 * s.scalar) - (t2 * s.e23))) + (((t3 * s.e13) - (t4 * s.e24)) + ((t5 * s.e14) - (t6 * s.e1234)))) - ((((t7 * s.e34) - (t8 * s.e25)) + ((t9 * s.e15) - (t10 * s.e1235))) - (((t11 * s.e35) + (t12 * s.e1245)) + ((t13 * s.e45) - (t14 * s.e2345))));
    const float t17 = (((t0 * s.e13) + ((t1 * s.e23) + (t2 * s.scalar))) - (((t3 * s.e12) + (t4 * s.e34)) - ((t5 * s.e1234) + (t6 * s.e14)))) + ((((t7 * s.e24) + (t8 * s.e35)) - ((t9 * s.e1235) + (t10 * s.e15))) - (((t11 * s.e25) - (t12 * s.e1345)) - ((t13 * s.e2345) + (t14 * s.e45))));
    const float t18 = (((t0 * s.e14) + ((t1 * s.e24) + (t2 * s.e34))) - (((t3 * s.e1234) - (t4 * s.scalar)) + ((t5 * s.e12) + (t6 * s.e13)))) - ((((t7 * s.e23) - (t8 * s.e45)) + ((t9 * s.e1245) + (t10 * s.e1345))) + (((t11 * s.e2345) + (t12 * s.e15)) + ((t13 * s.e25) + (t14 * s.e35))));
    const float t19 = (((t0 * s.e15) + ((t1 * s.e25) + (t2 * s.e35))) - (((t3 * s.e1235) - (t4 * s.e45)) + ((t5 * s.e1245) + (t6 * s.e1345)))) - ((((t7 * s.e2345) - (t8 * s.scalar)) + ((t9 * s.e12) + (t10 * s.e13))) + (((t11 * s.e23) + (t12 * s.e14)) + ((t13 * s.e24) + (t14 * s.e34))));
    cga_Vectorf r;
    r.e1 = (x.e1 + t15) + t15;
    r.e2 = (x.e2 + t16) + t16;
    r.e3 = (x.e3 + t17) + t17;
    r.e4 = (x.e4 + t18) + t18;
    r.e5 = (x.e5 + t19) + t19;
    return r;
}

/* rev(S) x S for a unit Vector S (S rev(S) = 1) and a Motor x; not the action otherwise. */
static inline cga_Motorf cga_vector_sandwich_unit_motorf(cga_Vectorf s, cga_Motorf x) {
    const float t0 = -(((s.e2 * x.e12) + (s.e3 * x.e13)) + ((s.e4 * x.e14) - (s.e5 * x.e15)));
    const float t1 = ((s.e1 * x.e12) - (s.e3 * x.e23)) - ((s.e4 * x.e24) - (s.e5 * x.e25));
    const float t2 = ((s.e1 * x.e13) + (s.e2 * x.e23)) - ((s.e4 * x.e34) - (s.e5 * x.e35));
    const float t3 = -((s.e4 * x.e1234) - (s.e5 * x.e1235));
    const float t4 = ((s.e1 * x.e14) + (s.e2 * x.e24)) + ((s.e3 * x.e34) + (s.e5 * x.e45));
    const float t5 = (s.e3 * x.e1234) + (s.e5 * x.e1245);
    const float t6 = -((s.e2 * x.e1234) - (s.e5 * x.e1345));
    const float t7 = (s.e1 * x.e1234) + (s.e5 * x.e2345);
    const float t8 = ((s.e1 * x.e15) + (s.e2 * x.e25)) + ((s.e3 * x.e35) + (s.e4 * x.e45));
    const float t9 = (s.e3 * x.e1235) + (s.e4 * x.e1245);
    const float t10 = -((s.e2 * x.e1235) - (s.e4 * x.e1345));
    const float t11 = (s.e1 * x.e1235) + (s.e4 * x.e2345);
    const float t12 = -((s.e2 * x.e1245) + (s.e3 * x.e1345));
    const float t13 = (s.e1 * x.e1245) - (s.e3 * x.e2345);
    const float t14 = (s.e1 * x.e1345) + (s.e2 * x.e2345);
    const float t15 = ((t0 * s.e2) - (t1 * s.e1)) + ((t3 * s.e3) + ((t5 * s.e4) - (t9 * s.e5)));
    const float t16 = ((t0 * s.e3) - (t2 * s.e1)) - ((t3 * s.e2) - ((t6 * s.e4) - (t10 * s.e5)));
    const float t17 = ((t1 * s.e3) - (t2 * s.e2)) + ((t3 * s.e1) + ((t7 * s.e4) - (t11 * s.e5)));
    const float t18 = ((t0 * s.e4) - (t4 * s.e1)) - ((t5 * s.e2) + ((t6 * s.e3) + (t12 * s.e5)));
    const float t19 = ((t1 * s.e4) - (t4 * s.e2)) + ((t5 * s.e1) - ((t7 * s.e3) + (t13 * s.e5)));
    const float t20 = ((t2 * s.e4) - (t4 * s.e3)) + ((t6 * s.e1) + ((t7 * s.e2) - (t14 * s.e5)));
    const float t21 = ((t0 * s.e5) - (t8 * s.e1)) - ((t9 * s.e2) + ((t10 * s.e3) + (t12 * s.e4)));
    const float t22 = ((t1 * s.e5) - (t8 * s.e2)) + ((t9 * s.e1) - ((t11 * s.e3) + (t13 * s.e4)));
    const float t23 = ((t2 * s.e5) - (t8 * s.e3)) + ((t10 * s.e1) + ((t11 * s.e2) - (t14 * s.e4)));
    const float t24 = ((t4 * s.e5) - (t8 * s.e4)) + ((t12 * s.e1) + ((t13 * s.e2) + (t14 * s.e3)));
    const float t25 = ((t3 * s.e4) - (t5 * s.e3)) + ((t6 * s.e2) - (t7 * s.e1));
    const float t26 = ((t3 * s.e5) - (t9 * s.e3)) + ((t10 * s.e2) - (t11 * s.e1));
    const float t27 = ((t5 * s.e5) - (t9 * s.e4)) + ((t12 * s.e2) - (t13 * s.e1));
    const float t28 = ((t6 * s.e5) - (t10 * s.e4)) + ((t12 * s.e3) - (t14 * s.e1));
    const float t29 = ((t7 * s.e5) - (t11 * s.e4)) + ((t13 * s.e3) - (t14 * s.e2));
    cga_Motorf r;
    r.scalar = x.scalar;
    r.e12 = (x.e12 + t15) + t15;
    r.e13 = (x.e13 + t16) + t16;
    r.e23 = (x.e23 + t17) + t17;
    r.e14 = (x.e14 + t18) + t18;
    r.e24 = (x.e24 + t19) + t19;
    r.e34 = (x.e34 + t20) + t20;
    r.e15 = (x.e15 + t21) + t21;
    r.e25 = (x.e25 + t22) + t22;
    r.e35 = (x.e35 + t23) + t23;
    r.e45 = (x.e45 + t24) + t24;
    r.e1234 = (x.e1234 + t25) + t25;
    r.e1235 = (x.e1235 + t26) + t26;
    r.e1245 = (x.e1245 + t27) + t27;
    r.e1345 = (x.e1345 + t28) + t28;
    r.e2345 = (x.e2345 + t29) + t29;
    return r;
}

/* rev(S) x S for a unit Vector S (S rev(S) = 1) and a Vector x; not the action otherwise. */
static inline cga_Vectorf cga_vector_sandwich_unit_vectorf(cga_Vectorf s, cga_Vectorf x) {
    const float t0 = (s.e1 * x.e2) - (s.e2 * x.e1);
    const float t1 = (s.e1 * x.e3) - (s.e3 * x.e1);
    const float t2 = (s.e2 * x.e3) - (s.e3 * x.e2);
    const float t3 = (s.e1 * x.e4) - (s.e4 * x.e1);
    const float t4 = (s.e2 * x.e4) - (s.e4 * x.e2);
    const float t5 = (s.e3 * x.e4) - (s.e4 * x.e3);
    const float t6 = (s.e1 * x.e5) - (s.e5 * x.e1);
    const float t7 = (s.e2 * x.e5) - (s.e5 * x.e2);
    const float t8 = (s.e3 * x.e5) - (s.e5 * x.e3);
    const float t9 = (s.e4 * x.e5) - (s.e5 * x.e4);
    const float t10 = ((t0 * s.e2) + (t1 * s.e3)) + ((t3 * s.e4) - (t6 * s.e5));
    const float t11 = -(((t0 * s.e1) - (t2 * s.e3)) - ((t4 * s.e4) - (t7 * s.e5)));
    const float t12 = -(((t1 * s.e1) + (t2 * s.e2)) - ((t5 * s.e4) - (t8 * s.e5)));
    const float t13 = -(((t3 * s.e1) + (t4 * s.e2)) + ((t5 * s.e3) + (t9 * s.e5)));
    const float t14 = -(((t6 * s.e1) + (t7 * s.e2)) + ((t8 * s.e3) + (t9 * s.e4)));
    cga_Vectorf r;
    r.e1 = (x.e1 + t10) + t10;
    r.e2 = (x.e2 + t11) + t11;
    r.e3 = (x.e3 + t12) + t12;
    r.e4 = (x.e4 + t13) + t13;
    r.e5 = (x.e5 + t14) + t14;
    return r;
}

#endif /* GAM_CGA_H */
