// g123inf: Motor=1,e12,e13,e23,e1inf,e2inf,e3inf,e123inf;Vector=grade1;Bivector=grade2; ops gp,sandwich,sandwich_unit,reverse,norm_squared,exp,log_unit,normalize
// Motor: the coefficients of scalar, e12, e13, e23, e1inf, e2inf, e3inf, e123inf.
struct g123inf_Motor {
    float scalar;
    float e12;
    float e13;
    float e23;
    float e1inf;
    float e2inf;
    float e3inf;
    float e123inf;
};

// Vector: the coefficients of e1, e2, e3, einf.
struct g123inf_Vector {
    float e1;
    float e2;
    float e3;
    float einf;
};

// Bivector: the coefficients of e12, e13, e23, e1inf, e2inf, e3inf.
struct g123inf_Bivector {
    float e12;
    float e13;
    float e23;
    float e1inf;
    float e2inf;
    float e3inf;
};

// The odd part of the algebra, declared automatically: some product of the declared types lands here.
// Odd: the coefficients of e1, e2, e3, einf, e123, e12inf, e13inf, e23inf.
struct g123inf_Odd {
    float e1;
    float e2;
    float e3;
    float einf;
    float e123;
    float e12inf;
    float e13inf;
    float e23inf;
};

// (sinc t, (cos t - sinc t) / t^2, cos t) from t^2 >= 0 (series below t = 1e-3).
vec3 g123inf_exp_factors(float theta2) {
    float theta = sqrt(theta2);
    if (theta < 0.001) {
        float t4 = theta2 * theta2;
        return vec3((1.0 - 0.16666667 * theta2) + 0.008333334 * t4, ((-0.33333334) + 0.033333335 * theta2) - 0.0011904762 * t4, (1.0 - 0.5 * theta2) + 0.041666668 * t4);
    } else {
        float si = sin(theta);
        float co = cos(theta);
        float inv = 1.0 / theta;
        float sinc = si * inv;
        return vec3(sinc, (co - sinc) * (inv * inv), co);
    }
}

// (t / sin t, (t cos t - sin t) / sin^3 t, 0) from sin t >= 0 and cos t, t = atan2 (series below t = 1e-3).
vec3 g123inf_log_factors(float si, float co) {
    float theta = atan(si, co);
    if (theta < 0.001) {
        float t2 = theta * theta;
        float t4 = t2 * t2;
        return vec3((1.0 + 0.16666667 * t2) + 0.019444445 * t4, ((-0.33333334) - 0.13333334 * t2) - 0.031746034 * t4, 0.0);
    } else {
        float r = 1.0 / si;
        float r2 = r * r;
        return vec3(theta * r, (theta * co - si) * (r2 * r), 0.0);
    }
}

// `gp` of a Motor and a Motor.
g123inf_Motor g123inf_motor_gp_motor(g123inf_Motor a, g123inf_Motor b) {
    float t0 = a.scalar * b.scalar;
    float t1 = a.scalar * b.e12;
    float t2 = a.scalar * b.e13;
    float t3 = a.scalar * b.e23;
    float t4 = a.scalar * b.e1inf;
    float t5 = a.scalar * b.e2inf;
    float t6 = a.scalar * b.e3inf;
    float t7 = a.scalar * b.e123inf;
    float t8 = a.e12 * b.scalar;
    float t9 = a.e12 * b.e12;
    float t10 = a.e12 * b.e13;
    float t11 = a.e12 * b.e23;
    float t12 = a.e12 * b.e1inf;
    float t13 = a.e12 * b.e2inf;
    float t14 = a.e12 * b.e3inf;
    float t15 = a.e12 * b.e123inf;
    float t16 = a.e13 * b.scalar;
    float t17 = a.e13 * b.e12;
    float t18 = a.e13 * b.e13;
    float t19 = a.e13 * b.e23;
    float t20 = a.e13 * b.e1inf;
    float t21 = a.e13 * b.e2inf;
    float t22 = a.e13 * b.e3inf;
    float t23 = a.e13 * b.e123inf;
    float t24 = a.e23 * b.scalar;
    float t25 = a.e23 * b.e12;
    float t26 = a.e23 * b.e13;
    float t27 = a.e23 * b.e23;
    float t28 = a.e23 * b.e1inf;
    float t29 = a.e23 * b.e2inf;
    float t30 = a.e23 * b.e3inf;
    float t31 = a.e23 * b.e123inf;
    float t32 = a.e1inf * b.scalar;
    float t33 = a.e1inf * b.e12;
    float t34 = a.e1inf * b.e13;
    float t35 = a.e1inf * b.e23;
    float t36 = a.e2inf * b.scalar;
    float t37 = a.e2inf * b.e12;
    float t38 = a.e2inf * b.e13;
    float t39 = a.e2inf * b.e23;
    float t40 = a.e3inf * b.scalar;
    float t41 = a.e3inf * b.e12;
    float t42 = a.e3inf * b.e13;
    float t43 = a.e3inf * b.e23;
    float t44 = a.e123inf * b.scalar;
    float t45 = a.e123inf * b.e12;
    float t46 = a.e123inf * b.e13;
    float t47 = a.e123inf * b.e23;
    return g123inf_Motor(
        ((t0 - t9) - t18) - t27,
        ((t1 + t8) + t26) - t19,
        ((t2 + t11) + t16) - t25,
        ((t3 + t17) + t24) - t10,
        ((((((t4 + t13) + t22) - t31) + t32) - t37) - t42) - t47,
        ((((((t5 + t23) + t30) - t12) + t33) + t36) + t46) - t43,
        ((((((t6 - t15) - t20) - t29) + t34) + t39) + t40) - t45,
        ((((((t7 + t14) + t28) - t21) + t35) + t41) + t44) - t38
    );
}

// `gp` of a Motor and a Vector.
g123inf_Odd g123inf_motor_gp_vector(g123inf_Motor a, g123inf_Vector b) {
    float t0 = a.scalar * b.e1;
    float t1 = a.scalar * b.e2;
    float t2 = a.scalar * b.e3;
    float t3 = a.scalar * b.einf;
    float t4 = a.e12 * b.e1;
    float t5 = a.e12 * b.e2;
    float t6 = a.e12 * b.e3;
    float t7 = a.e12 * b.einf;
    float t8 = a.e13 * b.e1;
    float t9 = a.e13 * b.e2;
    float t10 = a.e13 * b.e3;
    float t11 = a.e13 * b.einf;
    float t12 = a.e23 * b.e1;
    float t13 = a.e23 * b.e2;
    float t14 = a.e23 * b.e3;
    float t15 = a.e23 * b.einf;
    float t16 = a.e1inf * b.e1;
    float t17 = a.e1inf * b.e2;
    float t18 = a.e1inf * b.e3;
    float t19 = a.e2inf * b.e1;
    float t20 = a.e2inf * b.e2;
    float t21 = a.e2inf * b.e3;
    float t22 = a.e3inf * b.e1;
    float t23 = a.e3inf * b.e2;
    float t24 = a.e3inf * b.e3;
    float t25 = a.e123inf * b.e1;
    float t26 = a.e123inf * b.e2;
    float t27 = a.e123inf * b.e3;
    return g123inf_Odd(
        (t0 + t5) + t10,
        (t1 - t4) + t14,
        (t2 - t8) - t13,
        ((t3 - t16) - t20) - t24,
        (t6 - t9) + t12,
        ((t7 - t17) + t19) - t27,
        ((t11 - t18) + t22) + t26,
        ((t15 - t21) + t23) - t25
    );
}

// `gp` of a Motor and a Bivector.
g123inf_Motor g123inf_motor_gp_bivector(g123inf_Motor a, g123inf_Bivector b) {
    float t0 = a.scalar * b.e12;
    float t1 = a.scalar * b.e13;
    float t2 = a.scalar * b.e23;
    float t3 = a.scalar * b.e1inf;
    float t4 = a.scalar * b.e2inf;
    float t5 = a.scalar * b.e3inf;
    float t6 = a.e12 * b.e12;
    float t7 = a.e12 * b.e13;
    float t8 = a.e12 * b.e23;
    float t9 = a.e12 * b.e1inf;
    float t10 = a.e12 * b.e2inf;
    float t11 = a.e12 * b.e3inf;
    float t12 = a.e13 * b.e12;
    float t13 = a.e13 * b.e13;
    float t14 = a.e13 * b.e23;
    float t15 = a.e13 * b.e1inf;
    float t16 = a.e13 * b.e2inf;
    float t17 = a.e13 * b.e3inf;
    float t18 = a.e23 * b.e12;
    float t19 = a.e23 * b.e13;
    float t20 = a.e23 * b.e23;
    float t21 = a.e23 * b.e1inf;
    float t22 = a.e23 * b.e2inf;
    float t23 = a.e23 * b.e3inf;
    float t24 = a.e1inf * b.e12;
    float t25 = a.e1inf * b.e13;
    float t26 = a.e1inf * b.e23;
    float t27 = a.e2inf * b.e12;
    float t28 = a.e2inf * b.e13;
    float t29 = a.e2inf * b.e23;
    float t30 = a.e3inf * b.e12;
    float t31 = a.e3inf * b.e13;
    float t32 = a.e3inf * b.e23;
    float t33 = a.e123inf * b.e12;
    float t34 = a.e123inf * b.e13;
    float t35 = a.e123inf * b.e23;
    return g123inf_Motor(
        ((-t6) - t13) - t20,
        (t0 - t14) + t19,
        (t1 + t8) - t18,
        (t2 - t7) + t12,
        (((t3 + t10) + t17) - t27) - (t31 + t35),
        (((t4 - t9) + t23) + t24) - (t32 - t34),
        (((t5 - t15) - t22) + t25) + (t29 - t33),
        (((t11 - t16) + t21) + t26) - (t28 - t30)
    );
}

// `gp` of a Vector and a Motor.
g123inf_Odd g123inf_vector_gp_motor(g123inf_Vector a, g123inf_Motor b) {
    float t0 = a.e1 * b.scalar;
    float t1 = a.e1 * b.e12;
    float t2 = a.e1 * b.e13;
    float t3 = a.e1 * b.e23;
    float t4 = a.e1 * b.e1inf;
    float t5 = a.e1 * b.e2inf;
    float t6 = a.e1 * b.e3inf;
    float t7 = a.e1 * b.e123inf;
    float t8 = a.e2 * b.scalar;
    float t9 = a.e2 * b.e12;
    float t10 = a.e2 * b.e13;
    float t11 = a.e2 * b.e23;
    float t12 = a.e2 * b.e1inf;
    float t13 = a.e2 * b.e2inf;
    float t14 = a.e2 * b.e3inf;
    float t15 = a.e2 * b.e123inf;
    float t16 = a.e3 * b.scalar;
    float t17 = a.e3 * b.e12;
    float t18 = a.e3 * b.e13;
    float t19 = a.e3 * b.e23;
    float t20 = a.e3 * b.e1inf;
    float t21 = a.e3 * b.e2inf;
    float t22 = a.e3 * b.e3inf;
    float t23 = a.e3 * b.e123inf;
    float t24 = a.einf * b.scalar;
    float t25 = a.einf * b.e12;
    float t26 = a.einf * b.e13;
    float t27 = a.einf * b.e23;
    return g123inf_Odd(
        (t0 - t9) - t18,
        (t1 + t8) - t19,
        (t2 + t11) + t16,
        ((t4 + t13) + t22) + t24,
        (t3 - t10) + t17,
        ((t5 - t12) + t23) + t25,
        ((t6 - t15) - t20) + t26,
        ((t7 + t14) - t21) + t27
    );
}

// `gp` of a Vector and a Vector.
g123inf_Motor g123inf_vector_gp_vector(g123inf_Vector a, g123inf_Vector b) {
    float t0 = a.e1 * b.e1;
    float t1 = a.e1 * b.e2;
    float t2 = a.e1 * b.e3;
    float t3 = a.e1 * b.einf;
    float t4 = a.e2 * b.e1;
    float t5 = a.e2 * b.e2;
    float t6 = a.e2 * b.e3;
    float t7 = a.e2 * b.einf;
    float t8 = a.e3 * b.e1;
    float t9 = a.e3 * b.e2;
    float t10 = a.e3 * b.e3;
    float t11 = a.e3 * b.einf;
    float t12 = a.einf * b.e1;
    float t13 = a.einf * b.e2;
    float t14 = a.einf * b.e3;
    return g123inf_Motor(
        (t0 + t5) + t10,
        t1 - t4,
        t2 - t8,
        t6 - t9,
        t3 - t12,
        t7 - t13,
        t11 - t14,
        0.0
    );
}

// `gp` of a Vector and a Bivector.
g123inf_Odd g123inf_vector_gp_bivector(g123inf_Vector a, g123inf_Bivector b) {
    float t0 = a.e1 * b.e12;
    float t1 = a.e1 * b.e13;
    float t2 = a.e1 * b.e23;
    float t3 = a.e1 * b.e1inf;
    float t4 = a.e1 * b.e2inf;
    float t5 = a.e1 * b.e3inf;
    float t6 = a.e2 * b.e12;
    float t7 = a.e2 * b.e13;
    float t8 = a.e2 * b.e23;
    float t9 = a.e2 * b.e1inf;
    float t10 = a.e2 * b.e2inf;
    float t11 = a.e2 * b.e3inf;
    float t12 = a.e3 * b.e12;
    float t13 = a.e3 * b.e13;
    float t14 = a.e3 * b.e23;
    float t15 = a.e3 * b.e1inf;
    float t16 = a.e3 * b.e2inf;
    float t17 = a.e3 * b.e3inf;
    float t18 = a.einf * b.e12;
    float t19 = a.einf * b.e13;
    float t20 = a.einf * b.e23;
    return g123inf_Odd(
        (-t6) - t13,
        t0 - t14,
        t1 + t8,
        (t3 + t10) + t17,
        (t2 - t7) + t12,
        (t4 - t9) + t18,
        (t5 - t15) + t19,
        (t11 - t16) + t20
    );
}

// `gp` of a Bivector and a Motor.
g123inf_Motor g123inf_bivector_gp_motor(g123inf_Bivector a, g123inf_Motor b) {
    float t0 = a.e12 * b.scalar;
    float t1 = a.e12 * b.e12;
    float t2 = a.e12 * b.e13;
    float t3 = a.e12 * b.e23;
    float t4 = a.e12 * b.e1inf;
    float t5 = a.e12 * b.e2inf;
    float t6 = a.e12 * b.e3inf;
    float t7 = a.e12 * b.e123inf;
    float t8 = a.e13 * b.scalar;
    float t9 = a.e13 * b.e12;
    float t10 = a.e13 * b.e13;
    float t11 = a.e13 * b.e23;
    float t12 = a.e13 * b.e1inf;
    float t13 = a.e13 * b.e2inf;
    float t14 = a.e13 * b.e3inf;
    float t15 = a.e13 * b.e123inf;
    float t16 = a.e23 * b.scalar;
    float t17 = a.e23 * b.e12;
    float t18 = a.e23 * b.e13;
    float t19 = a.e23 * b.e23;
    float t20 = a.e23 * b.e1inf;
    float t21 = a.e23 * b.e2inf;
    float t22 = a.e23 * b.e3inf;
    float t23 = a.e23 * b.e123inf;
    float t24 = a.e1inf * b.scalar;
    float t25 = a.e1inf * b.e12;
    float t26 = a.e1inf * b.e13;
    float t27 = a.e1inf * b.e23;
    float t28 = a.e2inf * b.scalar;
    float t29 = a.e2inf * b.e12;
    float t30 = a.e2inf * b.e13;
    float t31 = a.e2inf * b.e23;
    float t32 = a.e3inf * b.scalar;
    float t33 = a.e3inf * b.e12;
    float t34 = a.e3inf * b.e13;
    float t35 = a.e3inf * b.e23;
    return g123inf_Motor(
        ((-t1) - t10) - t19,
        (t0 - t11) + t18,
        (t3 + t8) - t17,
        (t9 - t2) + t16,
        (((t5 + t14) - t23) + t24) - (t29 + t34),
        (((t15 - t4) + t22) + t25) + (t28 - t35),
        (((t26 - t12) - t21) - t7) + (t31 + t32),
        (((t6 - t13) + t20) + t27) - (t30 - t33)
    );
}

// `gp` of a Bivector and a Vector.
g123inf_Odd g123inf_bivector_gp_vector(g123inf_Bivector a, g123inf_Vector b) {
    float t0 = a.e12 * b.e1;
    float t1 = a.e12 * b.e2;
    float t2 = a.e12 * b.e3;
    float t3 = a.e12 * b.einf;
    float t4 = a.e13 * b.e1;
    float t5 = a.e13 * b.e2;
    float t6 = a.e13 * b.e3;
    float t7 = a.e13 * b.einf;
    float t8 = a.e23 * b.e1;
    float t9 = a.e23 * b.e2;
    float t10 = a.e23 * b.e3;
    float t11 = a.e23 * b.einf;
    float t12 = a.e1inf * b.e1;
    float t13 = a.e1inf * b.e2;
    float t14 = a.e1inf * b.e3;
    float t15 = a.e2inf * b.e1;
    float t16 = a.e2inf * b.e2;
    float t17 = a.e2inf * b.e3;
    float t18 = a.e3inf * b.e1;
    float t19 = a.e3inf * b.e2;
    float t20 = a.e3inf * b.e3;
    return g123inf_Odd(
        t1 + t6,
        t10 - t0,
        (-t4) - t9,
        ((-t12) - t16) - t20,
        (t2 - t5) + t8,
        (t3 - t13) + t15,
        (t7 - t14) + t18,
        (t11 - t17) + t19
    );
}

// `gp` of a Bivector and a Bivector.
g123inf_Motor g123inf_bivector_gp_bivector(g123inf_Bivector a, g123inf_Bivector b) {
    float t0 = a.e12 * b.e12;
    float t1 = a.e12 * b.e13;
    float t2 = a.e12 * b.e23;
    float t3 = a.e12 * b.e1inf;
    float t4 = a.e12 * b.e2inf;
    float t5 = a.e12 * b.e3inf;
    float t6 = a.e13 * b.e12;
    float t7 = a.e13 * b.e13;
    float t8 = a.e13 * b.e23;
    float t9 = a.e13 * b.e1inf;
    float t10 = a.e13 * b.e2inf;
    float t11 = a.e13 * b.e3inf;
    float t12 = a.e23 * b.e12;
    float t13 = a.e23 * b.e13;
    float t14 = a.e23 * b.e23;
    float t15 = a.e23 * b.e1inf;
    float t16 = a.e23 * b.e2inf;
    float t17 = a.e23 * b.e3inf;
    float t18 = a.e1inf * b.e12;
    float t19 = a.e1inf * b.e13;
    float t20 = a.e1inf * b.e23;
    float t21 = a.e2inf * b.e12;
    float t22 = a.e2inf * b.e13;
    float t23 = a.e2inf * b.e23;
    float t24 = a.e3inf * b.e12;
    float t25 = a.e3inf * b.e13;
    float t26 = a.e3inf * b.e23;
    return g123inf_Motor(
        ((-t0) - t7) - t14,
        t13 - t8,
        t2 - t12,
        t6 - t1,
        ((t4 + t11) - t21) - t25,
        ((t17 - t3) + t18) - t26,
        ((t19 - t16) - t9) + t23,
        (((t5 - t10) + t15) + t20) - (t22 - t24)
    );
}

// The reverse of a Motor.
g123inf_Motor g123inf_motor_reverse(g123inf_Motor x) {
    return g123inf_Motor(
        x.scalar,
        -x.e12,
        -x.e13,
        -x.e23,
        -x.e1inf,
        -x.e2inf,
        -x.e3inf,
        x.e123inf
    );
}

// The squared norm <x rev(x)>_0 of a Motor (may be negative or zero).
float g123inf_motor_norm_squared(g123inf_Motor x) {
    float t0 = x.scalar * x.scalar;
    float t1 = x.e12 * x.e12;
    float t2 = x.e13 * x.e13;
    float t3 = x.e23 * x.e23;
    return ((t0 + t1) + t2) + t3;
}

// The reverse of a Vector.
g123inf_Vector g123inf_vector_reverse(g123inf_Vector x) {
    return g123inf_Vector(
        x.e1,
        x.e2,
        x.e3,
        x.einf
    );
}

// The squared norm <x rev(x)>_0 of a Vector (may be negative or zero).
float g123inf_vector_norm_squared(g123inf_Vector x) {
    float t0 = x.e1 * x.e1;
    float t1 = x.e2 * x.e2;
    float t2 = x.e3 * x.e3;
    return (t0 + t1) + t2;
}

// The reverse of a Bivector.
g123inf_Bivector g123inf_bivector_reverse(g123inf_Bivector x) {
    return g123inf_Bivector(
        -x.e12,
        -x.e13,
        -x.e23,
        -x.e1inf,
        -x.e2inf,
        -x.e3inf
    );
}

// The squared norm <x rev(x)>_0 of a Bivector (may be negative or zero).
float g123inf_bivector_norm_squared(g123inf_Bivector x) {
    float t0 = x.e12 * x.e12;
    float t1 = x.e13 * x.e13;
    float t2 = x.e23 * x.e23;
    return (t0 + t1) + t2;
}

// rev(S) x S for a Motor S and a Motor x, in one fused kernel.
g123inf_Motor g123inf_motor_sandwich_motor(g123inf_Motor s, g123inf_Motor x) {
    float t0 = ((s.scalar * x.scalar) + (s.e12 * x.e12)) + ((s.e13 * x.e13) + (s.e23 * x.e23));
    float t1 = ((s.scalar * x.e12) + (s.e13 * x.e23)) - ((s.e12 * x.scalar) + (s.e23 * x.e13));
    float t2 = ((s.scalar * x.e13) + (s.e23 * x.e12)) - ((s.e12 * x.e23) + (s.e13 * x.scalar));
    float t3 = ((s.scalar * x.e23) + (s.e12 * x.e13)) - ((s.e13 * x.e12) + (s.e23 * x.scalar));
    float t4 = (((s.scalar * x.e1inf) + (s.e23 * x.e123inf)) + ((s.e2inf * x.e12) + (s.e3inf * x.e13))) - (((s.e12 * x.e2inf) + (s.e13 * x.e3inf)) + ((s.e1inf * x.scalar) + (s.e123inf * x.e23)));
    float t5 = (((s.scalar * x.e2inf) + (s.e12 * x.e1inf)) + ((s.e3inf * x.e23) + (s.e123inf * x.e13))) - (((s.e13 * x.e123inf) + (s.e23 * x.e3inf)) + ((s.e1inf * x.e12) + (s.e2inf * x.scalar)));
    float t6 = (((s.scalar * x.e3inf) + (s.e12 * x.e123inf)) + ((s.e13 * x.e1inf) + (s.e23 * x.e2inf))) - (((s.e1inf * x.e13) + (s.e2inf * x.e23)) + ((s.e3inf * x.scalar) + (s.e123inf * x.e12)));
    float t7 = (((s.scalar * x.e123inf) + (s.e13 * x.e2inf)) + ((s.e2inf * x.e13) + (s.e123inf * x.scalar))) - (((s.e12 * x.e3inf) + (s.e23 * x.e1inf)) + ((s.e1inf * x.e23) + (s.e3inf * x.e12)));
    return g123inf_Motor(
        ((t0 * s.scalar) - (t1 * s.e12)) - ((t2 * s.e13) + (t3 * s.e23)),
        ((t1 * s.scalar) + (t0 * s.e12)) + ((t3 * s.e13) - (t2 * s.e23)),
        ((t2 * s.scalar) - (t3 * s.e12)) + ((t0 * s.e13) + (t1 * s.e23)),
        ((t3 * s.scalar) + (t2 * s.e12)) - ((t1 * s.e13) - (t0 * s.e23)),
        (((t4 * s.scalar) - (t5 * s.e12)) - ((t6 * s.e13) + (t7 * s.e23))) + (((t0 * s.e1inf) + (t1 * s.e2inf)) + ((t2 * s.e3inf) - (t3 * s.e123inf))),
        (((t5 * s.scalar) + (t4 * s.e12)) + ((t7 * s.e13) - (t6 * s.e23))) - (((t1 * s.e1inf) - (t0 * s.e2inf)) - ((t3 * s.e3inf) + (t2 * s.e123inf))),
        (((t6 * s.scalar) - (t7 * s.e12)) + ((t4 * s.e13) + (t5 * s.e23))) - (((t2 * s.e1inf) + (t3 * s.e2inf)) - ((t0 * s.e3inf) - (t1 * s.e123inf))),
        (((t7 * s.scalar) + (t6 * s.e12)) - ((t5 * s.e13) - (t4 * s.e23))) + (((t3 * s.e1inf) - (t2 * s.e2inf)) + ((t1 * s.e3inf) + (t0 * s.e123inf)))
    );
}

// rev(S) x S for a Motor S and a Vector x, in one fused kernel.
g123inf_Vector g123inf_motor_sandwich_vector(g123inf_Motor s, g123inf_Vector x) {
    float t0 = -((s.e12 * x.e2) + (s.e13 * x.e3));
    float t1 = (s.e12 * x.e1) - (s.e23 * x.e3);
    float t2 = (s.e13 * x.e1) + (s.e23 * x.e2);
    float t3 = (s.e1inf * x.e1) + ((s.e2inf * x.e2) + (s.e3inf * x.e3));
    float t4 = -(s.e123inf * x.e3);
    float t5 = s.e123inf * x.e2;
    float t6 = -(s.e123inf * x.e1);
    float t7 = ((s.scalar * s.scalar) + (s.e12 * s.e12)) + ((s.e13 * s.e13) + (s.e23 * s.e23));
    float t8 = (t0 * s.scalar) - ((t1 * s.e12) + (t2 * s.e13));
    float t9 = (t1 * s.scalar) + ((t0 * s.e12) - (t2 * s.e23));
    float t10 = (t2 * s.scalar) + ((t0 * s.e13) + (t1 * s.e23));
    float t11 = ((t3 * s.scalar) - ((t4 * s.e12) + (t5 * s.e13))) - (((t6 * s.e23) - (t0 * s.e1inf)) - ((t1 * s.e2inf) + (t2 * s.e3inf)));
    return g123inf_Vector(
        (t7 * x.e1) + (t8 + t8),
        (t7 * x.e2) + (t9 + t9),
        (t7 * x.e3) + (t10 + t10),
        (t7 * x.einf) + (t11 + t11)
    );
}

// rev(S) x S for a Motor S and a Bivector x, in one fused kernel.
g123inf_Bivector g123inf_motor_sandwich_bivector(g123inf_Motor s, g123inf_Bivector x) {
    float t0 = (s.e12 * x.e12) + ((s.e13 * x.e13) + (s.e23 * x.e23));
    float t1 = (s.scalar * x.e12) + ((s.e13 * x.e23) - (s.e23 * x.e13));
    float t2 = (s.scalar * x.e13) + ((s.e23 * x.e12) - (s.e12 * x.e23));
    float t3 = (s.scalar * x.e23) + ((s.e12 * x.e13) - (s.e13 * x.e12));
    float t4 = ((s.scalar * x.e1inf) + ((s.e2inf * x.e12) + (s.e3inf * x.e13))) - ((s.e12 * x.e2inf) + ((s.e13 * x.e3inf) + (s.e123inf * x.e23)));
    float t5 = ((s.scalar * x.e2inf) + ((s.e12 * x.e1inf) + (s.e3inf * x.e23))) + ((s.e123inf * x.e13) - ((s.e23 * x.e3inf) + (s.e1inf * x.e12)));
    float t6 = ((s.scalar * x.e3inf) + ((s.e13 * x.e1inf) + (s.e23 * x.e2inf))) - ((s.e1inf * x.e13) + ((s.e2inf * x.e23) + (s.e123inf * x.e12)));
    float t7 = ((s.e13 * x.e2inf) + ((s.e2inf * x.e13) - (s.e12 * x.e3inf))) - ((s.e23 * x.e1inf) + ((s.e1inf * x.e23) + (s.e3inf * x.e12)));
    return g123inf_Bivector(
        ((t1 * s.scalar) + (t0 * s.e12)) + ((t3 * s.e13) - (t2 * s.e23)),
        ((t2 * s.scalar) - (t3 * s.e12)) + ((t0 * s.e13) + (t1 * s.e23)),
        ((t3 * s.scalar) + (t2 * s.e12)) - ((t1 * s.e13) - (t0 * s.e23)),
        (((t4 * s.scalar) - (t5 * s.e12)) - ((t6 * s.e13) + (t7 * s.e23))) + (((t0 * s.e1inf) + (t1 * s.e2inf)) + ((t2 * s.e3inf) - (t3 * s.e123inf))),
        (((t5 * s.scalar) + (t4 * s.e12)) + ((t7 * s.e13) - (t6 * s.e23))) - (((t1 * s.e1inf) - (t0 * s.e2inf)) - ((t3 * s.e3inf) + (t2 * s.e123inf))),
        (((t6 * s.scalar) - (t7 * s.e12)) + ((t4 * s.e13) + (t5 * s.e23))) - (((t2 * s.e1inf) + (t3 * s.e2inf)) - ((t0 * s.e3inf) - (t1 * s.e123inf)))
    );
}

// rev(S) x S for a Vector S and a Motor x, in one fused kernel.
g123inf_Motor g123inf_vector_sandwich_motor(g123inf_Vector s, g123inf_Motor x) {
    float t0 = (s.e1 * x.scalar) - ((s.e2 * x.e12) + (s.e3 * x.e13));
    float t1 = (s.e1 * x.e12) + ((s.e2 * x.scalar) - (s.e3 * x.e23));
    float t2 = (s.e1 * x.e13) + ((s.e2 * x.e23) + (s.e3 * x.scalar));
    float t3 = (s.e1 * x.e23) + ((s.e3 * x.e12) - (s.e2 * x.e13));
    float t4 = ((s.e1 * x.e1inf) + (s.e2 * x.e2inf)) + ((s.e3 * x.e3inf) + (s.einf * x.scalar));
    float t5 = ((s.e1 * x.e2inf) + (s.e3 * x.e123inf)) + ((s.einf * x.e12) - (s.e2 * x.e1inf));
    float t6 = ((s.e1 * x.e3inf) + (s.einf * x.e13)) - ((s.e2 * x.e123inf) + (s.e3 * x.e1inf));
    float t7 = ((s.e1 * x.e123inf) + (s.e2 * x.e3inf)) + ((s.einf * x.e23) - (s.e3 * x.e2inf));
    return g123inf_Motor(
        (t0 * s.e1) + ((t1 * s.e2) + (t2 * s.e3)),
        (t0 * s.e2) - ((t1 * s.e1) - (t3 * s.e3)),
        (t0 * s.e3) - ((t2 * s.e1) + (t3 * s.e2)),
        (t3 * s.e1) - ((t2 * s.e2) - (t1 * s.e3)),
        ((t0 * s.einf) - (t4 * s.e1)) - ((t5 * s.e2) + (t6 * s.e3)),
        ((t5 * s.e1) - (t4 * s.e2)) - ((t7 * s.e3) - (t1 * s.einf)),
        ((t6 * s.e1) + (t7 * s.e2)) - ((t4 * s.e3) - (t2 * s.einf)),
        ((t6 * s.e2) - (t7 * s.e1)) - ((t5 * s.e3) - (t3 * s.einf))
    );
}

// rev(S) x S for a Vector S and a Vector x, in one fused kernel.
g123inf_Vector g123inf_vector_sandwich_vector(g123inf_Vector s, g123inf_Vector x) {
    float t0 = (s.e1 * x.e1) + ((s.e2 * x.e2) + (s.e3 * x.e3));
    float t1 = (s.e1 * x.e2) - (s.e2 * x.e1);
    float t2 = (s.e1 * x.e3) - (s.e3 * x.e1);
    float t3 = (s.e2 * x.e3) - (s.e3 * x.e2);
    float t4 = (s.e1 * x.einf) - (s.einf * x.e1);
    float t5 = (s.e2 * x.einf) - (s.einf * x.e2);
    float t6 = (s.e3 * x.einf) - (s.einf * x.e3);
    return g123inf_Vector(
        (t0 * s.e1) + ((t1 * s.e2) + (t2 * s.e3)),
        (t0 * s.e2) - ((t1 * s.e1) - (t3 * s.e3)),
        (t0 * s.e3) - ((t2 * s.e1) + (t3 * s.e2)),
        ((t0 * s.einf) - (t4 * s.e1)) - ((t5 * s.e2) + (t6 * s.e3))
    );
}

// rev(S) x S for a Vector S and a Bivector x, in one fused kernel.
g123inf_Bivector g123inf_vector_sandwich_bivector(g123inf_Vector s, g123inf_Bivector x) {
    float t0 = -((s.e2 * x.e12) + (s.e3 * x.e13));
    float t1 = (s.e1 * x.e12) - (s.e3 * x.e23);
    float t2 = (s.e1 * x.e13) + (s.e2 * x.e23);
    float t3 = (s.e1 * x.e1inf) + ((s.e2 * x.e2inf) + (s.e3 * x.e3inf));
    float t4 = (s.e1 * s.e1) + ((s.e2 * s.e2) + (s.e3 * s.e3));
    float t5 = (t0 * s.e2) - (t1 * s.e1);
    float t6 = (t0 * s.e3) - (t2 * s.e1);
    float t7 = (t1 * s.e3) - (t2 * s.e2);
    float t8 = (t0 * s.einf) - (t3 * s.e1);
    float t9 = (t1 * s.einf) - (t3 * s.e2);
    float t10 = (t2 * s.einf) - (t3 * s.e3);
    return g123inf_Bivector(
        (t4 * x.e12) + (t5 + t5),
        (t4 * x.e13) + (t6 + t6),
        (t4 * x.e23) + (t7 + t7),
        (t4 * x.e1inf) + (t8 + t8),
        (t4 * x.e2inf) + (t9 + t9),
        (t4 * x.e3inf) + (t10 + t10)
    );
}

// rev(S) x S for a Bivector S and a Motor x, in one fused kernel.
g123inf_Motor g123inf_bivector_sandwich_motor(g123inf_Bivector s, g123inf_Motor x) {
    float t0 = (s.e12 * x.e12) + ((s.e13 * x.e13) + (s.e23 * x.e23));
    float t1 = (s.e13 * x.e23) - ((s.e12 * x.scalar) + (s.e23 * x.e13));
    float t2 = (s.e23 * x.e12) - ((s.e12 * x.e23) + (s.e13 * x.scalar));
    float t3 = (s.e12 * x.e13) - ((s.e13 * x.e12) + (s.e23 * x.scalar));
    float t4 = ((s.e23 * x.e123inf) + ((s.e2inf * x.e12) + (s.e3inf * x.e13))) - ((s.e12 * x.e2inf) + ((s.e13 * x.e3inf) + (s.e1inf * x.scalar)));
    float t5 = ((s.e12 * x.e1inf) + ((s.e3inf * x.e23) - (s.e13 * x.e123inf))) - ((s.e23 * x.e3inf) + ((s.e1inf * x.e12) + (s.e2inf * x.scalar)));
    float t6 = ((s.e12 * x.e123inf) + ((s.e13 * x.e1inf) + (s.e23 * x.e2inf))) - ((s.e1inf * x.e13) + ((s.e2inf * x.e23) + (s.e3inf * x.scalar)));
    float t7 = ((s.e13 * x.e2inf) + ((s.e2inf * x.e13) - (s.e12 * x.e3inf))) - ((s.e23 * x.e1inf) + ((s.e1inf * x.e23) + (s.e3inf * x.e12)));
    return g123inf_Motor(
        -((t1 * s.e12) + ((t2 * s.e13) + (t3 * s.e23))),
        (t0 * s.e12) + ((t3 * s.e13) - (t2 * s.e23)),
        (t0 * s.e13) - ((t3 * s.e12) - (t1 * s.e23)),
        (t2 * s.e12) - ((t1 * s.e13) - (t0 * s.e23)),
        ((t0 * s.e1inf) - ((t5 * s.e12) + (t6 * s.e13))) - ((t7 * s.e23) - ((t1 * s.e2inf) + (t2 * s.e3inf))),
        ((t4 * s.e12) + ((t7 * s.e13) - (t6 * s.e23))) - ((t1 * s.e1inf) - ((t0 * s.e2inf) + (t3 * s.e3inf))),
        ((t4 * s.e13) - ((t7 * s.e12) - (t5 * s.e23))) - ((t2 * s.e1inf) + ((t3 * s.e2inf) - (t0 * s.e3inf))),
        ((t6 * s.e12) - ((t5 * s.e13) - (t4 * s.e23))) + ((t3 * s.e1inf) - ((t2 * s.e2inf) - (t1 * s.e3inf)))
    );
}

// rev(S) x S for a Bivector S and a Vector x, in one fused kernel.
g123inf_Vector g123inf_bivector_sandwich_vector(g123inf_Bivector s, g123inf_Vector x) {
    float t0 = -((s.e12 * x.e2) + (s.e13 * x.e3));
    float t1 = (s.e12 * x.e1) - (s.e23 * x.e3);
    float t2 = (s.e13 * x.e1) + (s.e23 * x.e2);
    float t3 = (s.e12 * s.e12) + ((s.e13 * s.e13) + (s.e23 * s.e23));
    float t4 = -((t1 * s.e12) + (t2 * s.e13));
    float t5 = (t0 * s.e12) - (t2 * s.e23);
    float t6 = (t0 * s.e13) + (t1 * s.e23);
    float t7 = (t0 * s.e1inf) + ((t1 * s.e2inf) + (t2 * s.e3inf));
    return g123inf_Vector(
        (t3 * x.e1) + (t4 + t4),
        (t3 * x.e2) + (t5 + t5),
        (t3 * x.e3) + (t6 + t6),
        (t3 * x.einf) + (t7 + t7)
    );
}

// rev(S) x S for a Bivector S and a Bivector x, in one fused kernel.
g123inf_Bivector g123inf_bivector_sandwich_bivector(g123inf_Bivector s, g123inf_Bivector x) {
    float t0 = (s.e12 * x.e12) + ((s.e13 * x.e13) + (s.e23 * x.e23));
    float t1 = (s.e13 * x.e23) - (s.e23 * x.e13);
    float t2 = (s.e23 * x.e12) - (s.e12 * x.e23);
    float t3 = (s.e12 * x.e13) - (s.e13 * x.e12);
    float t4 = ((s.e2inf * x.e12) + (s.e3inf * x.e13)) - ((s.e12 * x.e2inf) + (s.e13 * x.e3inf));
    float t5 = ((s.e12 * x.e1inf) + (s.e3inf * x.e23)) - ((s.e23 * x.e3inf) + (s.e1inf * x.e12));
    float t6 = ((s.e13 * x.e1inf) + (s.e23 * x.e2inf)) - ((s.e1inf * x.e13) + (s.e2inf * x.e23));
    float t7 = ((s.e13 * x.e2inf) + ((s.e2inf * x.e13) - (s.e12 * x.e3inf))) - ((s.e23 * x.e1inf) + ((s.e1inf * x.e23) + (s.e3inf * x.e12)));
    return g123inf_Bivector(
        (t0 * s.e12) + ((t3 * s.e13) - (t2 * s.e23)),
        (t0 * s.e13) - ((t3 * s.e12) - (t1 * s.e23)),
        (t2 * s.e12) - ((t1 * s.e13) - (t0 * s.e23)),
        ((t0 * s.e1inf) - ((t5 * s.e12) + (t6 * s.e13))) - ((t7 * s.e23) - ((t1 * s.e2inf) + (t2 * s.e3inf))),
        ((t4 * s.e12) + ((t7 * s.e13) - (t6 * s.e23))) - ((t1 * s.e1inf) - ((t0 * s.e2inf) + (t3 * s.e3inf))),
        ((t4 * s.e13) - ((t7 * s.e12) - (t5 * s.e23))) - ((t2 * s.e1inf) + ((t3 * s.e2inf) - (t0 * s.e3inf)))
    );
}

// rev(S) x S for a unit Motor S (S rev(S) = 1) and a Motor x; not the action otherwise.
g123inf_Motor g123inf_motor_sandwich_unit_motor(g123inf_Motor s, g123inf_Motor x) {
    float t0 = (s.e13 * x.e23) - (s.e23 * x.e13);
    float t1 = -((s.e12 * x.e23) - (s.e23 * x.e12));
    float t2 = (s.e12 * x.e13) - (s.e13 * x.e12);
    float t3 = -(((s.e12 * x.e2inf) + (s.e13 * x.e3inf)) - ((s.e2inf * x.e12) + (s.e3inf * x.e13)));
    float t4 = ((s.e12 * x.e1inf) - (s.e23 * x.e3inf)) - ((s.e1inf * x.e12) - (s.e3inf * x.e23));
    float t5 = ((s.e13 * x.e1inf) + (s.e23 * x.e2inf)) - ((s.e1inf * x.e13) + (s.e2inf * x.e23));
    float t6 = (t0 * s.scalar) - ((t1 * s.e23) - (t2 * s.e13));
    float t7 = (t0 * s.e23) + ((t1 * s.scalar) - (t2 * s.e12));
    float t8 = -((t0 * s.e13) - ((t1 * s.e12) + (t2 * s.scalar)));
    float t9 = ((t0 * s.e2inf) + ((t1 * s.e3inf) - (t2 * s.e123inf))) + ((t3 * s.scalar) - ((t4 * s.e12) + (t5 * s.e13)));
    float t10 = -(((t0 * s.e1inf) - ((t1 * s.e123inf) + (t2 * s.e3inf))) - ((t3 * s.e12) + ((t4 * s.scalar) - (t5 * s.e23))));
    float t11 = -(((t0 * s.e123inf) + ((t1 * s.e1inf) + (t2 * s.e2inf))) - ((t3 * s.e13) + ((t4 * s.e23) + (t5 * s.scalar))));
    return g123inf_Motor(
        x.scalar,
        (x.e12 + t6) + t6,
        (x.e13 + t7) + t7,
        (x.e23 + t8) + t8,
        (x.e1inf + t9) + t9,
        (x.e2inf + t10) + t10,
        (x.e3inf + t11) + t11,
        x.e123inf
    );
}

// rev(S) x S for a unit Motor S (S rev(S) = 1) and a Vector x; not the action otherwise.
g123inf_Vector g123inf_motor_sandwich_unit_vector(g123inf_Motor s, g123inf_Vector x) {
    float t0 = -((s.e12 * x.e2) + (s.e13 * x.e3));
    float t1 = (s.e12 * x.e1) - (s.e23 * x.e3);
    float t2 = (s.e13 * x.e1) + (s.e23 * x.e2);
    float t3 = (s.e1inf * x.e1) + ((s.e2inf * x.e2) + (s.e3inf * x.e3));
    float t4 = -(s.e123inf * x.e3);
    float t5 = s.e123inf * x.e2;
    float t6 = -(s.e123inf * x.e1);
    float t7 = (t0 * s.scalar) - ((t1 * s.e12) + (t2 * s.e13));
    float t8 = (t0 * s.e12) + ((t1 * s.scalar) - (t2 * s.e23));
    float t9 = (t0 * s.e13) + ((t1 * s.e23) + (t2 * s.scalar));
    float t10 = ((t0 * s.e1inf) + ((t1 * s.e2inf) + (t2 * s.e3inf))) + (((t3 * s.scalar) - (t4 * s.e12)) - ((t5 * s.e13) + (t6 * s.e23)));
    return g123inf_Vector(
        (x.e1 + t7) + t7,
        (x.e2 + t8) + t8,
        (x.e3 + t9) + t9,
        (x.einf + t10) + t10
    );
}

// rev(S) x S for a unit Motor S (S rev(S) = 1) and a Bivector x; not the action otherwise.
g123inf_Bivector g123inf_motor_sandwich_unit_bivector(g123inf_Motor s, g123inf_Bivector x) {
    float t0 = (s.e13 * x.e23) - (s.e23 * x.e13);
    float t1 = -((s.e12 * x.e23) - (s.e23 * x.e12));
    float t2 = (s.e12 * x.e13) - (s.e13 * x.e12);
    float t3 = -(((s.e12 * x.e2inf) + (s.e13 * x.e3inf)) - ((s.e2inf * x.e12) + (s.e3inf * x.e13)));
    float t4 = ((s.e12 * x.e1inf) - (s.e23 * x.e3inf)) - ((s.e1inf * x.e12) - (s.e3inf * x.e23));
    float t5 = ((s.e13 * x.e1inf) + (s.e23 * x.e2inf)) - ((s.e1inf * x.e13) + (s.e2inf * x.e23));
    float t6 = (t0 * s.scalar) - ((t1 * s.e23) - (t2 * s.e13));
    float t7 = (t0 * s.e23) + ((t1 * s.scalar) - (t2 * s.e12));
    float t8 = -((t0 * s.e13) - ((t1 * s.e12) + (t2 * s.scalar)));
    float t9 = ((t0 * s.e2inf) + ((t1 * s.e3inf) - (t2 * s.e123inf))) + ((t3 * s.scalar) - ((t4 * s.e12) + (t5 * s.e13)));
    float t10 = -(((t0 * s.e1inf) - ((t1 * s.e123inf) + (t2 * s.e3inf))) - ((t3 * s.e12) + ((t4 * s.scalar) - (t5 * s.e23))));
    float t11 = -(((t0 * s.e123inf) + ((t1 * s.e1inf) + (t2 * s.e2inf))) - ((t3 * s.e13) + ((t4 * s.e23) + (t5 * s.scalar))));
    return g123inf_Bivector(
        (x.e12 + t6) + t6,
        (x.e13 + t7) + t7,
        (x.e23 + t8) + t8,
        (x.e1inf + t9) + t9,
        (x.e2inf + t10) + t10,
        (x.e3inf + t11) + t11
    );
}

// rev(S) x S for a unit Vector S (S rev(S) = 1) and a Motor x; not the action otherwise.
g123inf_Motor g123inf_vector_sandwich_unit_motor(g123inf_Vector s, g123inf_Motor x) {
    float t0 = -((s.e2 * x.e12) + (s.e3 * x.e13));
    float t1 = (s.e1 * x.e12) - (s.e3 * x.e23);
    float t2 = (s.e1 * x.e13) + (s.e2 * x.e23);
    float t3 = (s.e1 * x.e1inf) + ((s.e2 * x.e2inf) + (s.e3 * x.e3inf));
    float t4 = s.e3 * x.e123inf;
    float t5 = -(s.e2 * x.e123inf);
    float t6 = s.e1 * x.e123inf;
    float t7 = (t0 * s.e2) - (t1 * s.e1);
    float t8 = (t0 * s.e3) - (t2 * s.e1);
    float t9 = (t1 * s.e3) - (t2 * s.e2);
    float t10 = ((t0 * s.einf) - (t3 * s.e1)) - ((t4 * s.e2) + (t5 * s.e3));
    float t11 = ((t1 * s.einf) - (t3 * s.e2)) + ((t4 * s.e1) - (t6 * s.e3));
    float t12 = ((t2 * s.einf) - (t3 * s.e3)) + ((t5 * s.e1) + (t6 * s.e2));
    float t13 = -((t4 * s.e3) - ((t5 * s.e2) - (t6 * s.e1)));
    return g123inf_Motor(
        x.scalar,
        (x.e12 + t7) + t7,
        (x.e13 + t8) + t8,
        (x.e23 + t9) + t9,
        (x.e1inf + t10) + t10,
        (x.e2inf + t11) + t11,
        (x.e3inf + t12) + t12,
        (x.e123inf + t13) + t13
    );
}

// rev(S) x S for a unit Vector S (S rev(S) = 1) and a Vector x; not the action otherwise.
g123inf_Vector g123inf_vector_sandwich_unit_vector(g123inf_Vector s, g123inf_Vector x) {
    float t0 = (s.e1 * x.e2) - (s.e2 * x.e1);
    float t1 = (s.e1 * x.e3) - (s.e3 * x.e1);
    float t2 = (s.e2 * x.e3) - (s.e3 * x.e2);
    float t3 = (s.e1 * x.einf) - (s.einf * x.e1);
    float t4 = (s.e2 * x.einf) - (s.einf * x.e2);
    float t5 = (s.e3 * x.einf) - (s.einf * x.e3);
    float t6 = (t0 * s.e2) + (t1 * s.e3);
    float t7 = -((t0 * s.e1) - (t2 * s.e3));
    float t8 = -((t1 * s.e1) + (t2 * s.e2));
    float t9 = -((t3 * s.e1) + ((t4 * s.e2) + (t5 * s.e3)));
    return g123inf_Vector(
        (x.e1 + t6) + t6,
        (x.e2 + t7) + t7,
        (x.e3 + t8) + t8,
        (x.einf + t9) + t9
    );
}

// rev(S) x S for a unit Vector S (S rev(S) = 1) and a Bivector x; not the action otherwise.
g123inf_Bivector g123inf_vector_sandwich_unit_bivector(g123inf_Vector s, g123inf_Bivector x) {
    float t0 = -((s.e2 * x.e12) + (s.e3 * x.e13));
    float t1 = (s.e1 * x.e12) - (s.e3 * x.e23);
    float t2 = (s.e1 * x.e13) + (s.e2 * x.e23);
    float t3 = (s.e1 * x.e1inf) + ((s.e2 * x.e2inf) + (s.e3 * x.e3inf));
    float t4 = (t0 * s.e2) - (t1 * s.e1);
    float t5 = (t0 * s.e3) - (t2 * s.e1);
    float t6 = (t1 * s.e3) - (t2 * s.e2);
    float t7 = (t0 * s.einf) - (t3 * s.e1);
    float t8 = (t1 * s.einf) - (t3 * s.e2);
    float t9 = (t2 * s.einf) - (t3 * s.e3);
    return g123inf_Bivector(
        (x.e12 + t4) + t4,
        (x.e13 + t5) + t5,
        (x.e23 + t6) + t6,
        (x.e1inf + t7) + t7,
        (x.e2inf + t8) + t8,
        (x.e3inf + t9) + t9
    );
}

// rev(S) x S for a unit Bivector S (S rev(S) = 1) and a Motor x; not the action otherwise.
g123inf_Motor g123inf_bivector_sandwich_unit_motor(g123inf_Bivector s, g123inf_Motor x) {
    float t0 = (s.e13 * x.e23) - (s.e23 * x.e13);
    float t1 = -((s.e12 * x.e23) - (s.e23 * x.e12));
    float t2 = (s.e12 * x.e13) - (s.e13 * x.e12);
    float t3 = -(((s.e12 * x.e2inf) + (s.e13 * x.e3inf)) - ((s.e2inf * x.e12) + (s.e3inf * x.e13)));
    float t4 = ((s.e12 * x.e1inf) - (s.e23 * x.e3inf)) - ((s.e1inf * x.e12) - (s.e3inf * x.e23));
    float t5 = ((s.e13 * x.e1inf) + (s.e23 * x.e2inf)) - ((s.e1inf * x.e13) + (s.e2inf * x.e23));
    float t6 = -((t1 * s.e23) - (t2 * s.e13));
    float t7 = (t0 * s.e23) - (t2 * s.e12);
    float t8 = -((t0 * s.e13) - (t1 * s.e12));
    float t9 = ((t0 * s.e2inf) + (t1 * s.e3inf)) - ((t4 * s.e12) + (t5 * s.e13));
    float t10 = -(((t0 * s.e1inf) - (t2 * s.e3inf)) - ((t3 * s.e12) - (t5 * s.e23)));
    float t11 = -(((t1 * s.e1inf) + (t2 * s.e2inf)) - ((t3 * s.e13) + (t4 * s.e23)));
    return g123inf_Motor(
        x.scalar,
        (x.e12 + t6) + t6,
        (x.e13 + t7) + t7,
        (x.e23 + t8) + t8,
        (x.e1inf + t9) + t9,
        (x.e2inf + t10) + t10,
        (x.e3inf + t11) + t11,
        x.e123inf
    );
}

// rev(S) x S for a unit Bivector S (S rev(S) = 1) and a Vector x; not the action otherwise.
g123inf_Vector g123inf_bivector_sandwich_unit_vector(g123inf_Bivector s, g123inf_Vector x) {
    float t0 = -((s.e12 * x.e2) + (s.e13 * x.e3));
    float t1 = (s.e12 * x.e1) - (s.e23 * x.e3);
    float t2 = (s.e13 * x.e1) + (s.e23 * x.e2);
    float t3 = -((t1 * s.e12) + (t2 * s.e13));
    float t4 = (t0 * s.e12) - (t2 * s.e23);
    float t5 = (t0 * s.e13) + (t1 * s.e23);
    float t6 = (t0 * s.e1inf) + ((t1 * s.e2inf) + (t2 * s.e3inf));
    return g123inf_Vector(
        (x.e1 + t3) + t3,
        (x.e2 + t4) + t4,
        (x.e3 + t5) + t5,
        (x.einf + t6) + t6
    );
}

// rev(S) x S for a unit Bivector S (S rev(S) = 1) and a Bivector x; not the action otherwise.
g123inf_Bivector g123inf_bivector_sandwich_unit_bivector(g123inf_Bivector s, g123inf_Bivector x) {
    float t0 = (s.e13 * x.e23) - (s.e23 * x.e13);
    float t1 = -((s.e12 * x.e23) - (s.e23 * x.e12));
    float t2 = (s.e12 * x.e13) - (s.e13 * x.e12);
    float t3 = -(((s.e12 * x.e2inf) + (s.e13 * x.e3inf)) - ((s.e2inf * x.e12) + (s.e3inf * x.e13)));
    float t4 = ((s.e12 * x.e1inf) - (s.e23 * x.e3inf)) - ((s.e1inf * x.e12) - (s.e3inf * x.e23));
    float t5 = ((s.e13 * x.e1inf) + (s.e23 * x.e2inf)) - ((s.e1inf * x.e13) + (s.e2inf * x.e23));
    float t6 = -((t1 * s.e23) - (t2 * s.e13));
    float t7 = (t0 * s.e23) - (t2 * s.e12);
    float t8 = -((t0 * s.e13) - (t1 * s.e12));
    float t9 = ((t0 * s.e2inf) + (t1 * s.e3inf)) - ((t4 * s.e12) + (t5 * s.e13));
    float t10 = -(((t0 * s.e1inf) - (t2 * s.e3inf)) - ((t3 * s.e12) - (t5 * s.e23)));
    float t11 = -(((t1 * s.e1inf) + (t2 * s.e2inf)) - ((t3 * s.e13) + (t4 * s.e23)));
    return g123inf_Bivector(
        (x.e12 + t6) + t6,
        (x.e13 + t7) + t7,
        (x.e23 + t8) + t8,
        (x.e1inf + t9) + t9,
        (x.e2inf + t10) + t10,
        (x.e3inf + t11) + t11
    );
}

// exp of a Bivector: a unit Motor (closed form; non-finite input gives non-finite output).
g123inf_Motor g123inf_bivector_exp(g123inf_Bivector x) {
    float t0 = ((x.e12 * x.e12) + (x.e13 * x.e13)) + (x.e23 * x.e23);
    vec3 t1 = g123inf_exp_factors(t0);
    float t2 = ((x.e12 * x.e3inf) - (x.e13 * x.e2inf)) + (x.e23 * x.e1inf);
    float t3 = t2 * t1.y;
    return g123inf_Motor(
        t1.z,
        t1.x * x.e12,
        t1.x * x.e13,
        t1.x * x.e23,
        (t1.x * x.e1inf) + (t3 * x.e23),
        (t1.x * x.e2inf) - (t3 * x.e13),
        (t1.x * x.e3inf) + (t3 * x.e12),
        t2 * t1.x
    );
}

// log of a unit Motor (m rev(m) = 1): the Bivector B with exp(B) = m, angle in [0, pi); a full turn gives non-finite output.
g123inf_Bivector g123inf_motor_log_unit(g123inf_Motor x) {
    float t0 = sqrt(((x.e12 * x.e12) + (x.e13 * x.e13)) + (x.e23 * x.e23));
    vec3 t1 = g123inf_log_factors(t0, x.scalar);
    float t2 = x.e123inf * t1.y;
    return g123inf_Bivector(
        t1.x * x.e12,
        t1.x * x.e13,
        t1.x * x.e23,
        (t1.x * x.e1inf) - (t2 * x.e23),
        (t1.x * x.e2inf) + (t2 * x.e13),
        (t1.x * x.e3inf) - (t2 * x.e12)
    );
}

// m / sqrt(m rev(m)) for a Motor: a unit Motor; a non-positive norm gives non-finite output.
g123inf_Motor g123inf_motor_normalize(g123inf_Motor x) {
    float t0 = (x.scalar * x.scalar) - (((-(x.e12 * x.e12)) - (x.e13 * x.e13)) - (x.e23 * x.e23));
    float t1 = 1.0 / t0;
    float t2 = (x.scalar * x.e123inf) - (((x.e12 * x.e3inf) - (x.e13 * x.e2inf)) + (x.e23 * x.e1inf));
    float t3 = sqrt(t1);
    float t4 = (-(t2 * t3)) * t1;
    return g123inf_Motor(
        x.scalar * t3,
        x.e12 * t3,
        x.e13 * t3,
        x.e23 * t3,
        (x.e1inf * t3) + (-(t4 * x.e23)),
        (x.e2inf * t3) + (t4 * x.e13),
        (x.e3inf * t3) + (-(t4 * x.e12)),
        (x.e123inf * t3) + (x.scalar * t4)
    );
}

