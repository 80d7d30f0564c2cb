// g123inf: Motor=1,e12,e13,e23,e1inf,e2inf,e3inf,e123inf;Vector=grade1;Bivector=grade2; ops gp,sandwich,sandwich_unit,reverse,norm_squared,exp,log_unit,normalize
// Motor: the coefficients of scalar, e12, e13, e23, e1inf, e2inf, e3inf, e123inf.
struct g123inf_Motor {
    scalar: f32,
    e12: f32,
    e13: f32,
    e23: f32,
    e1inf: f32,
    e2inf: f32,
    e3inf: f32,
    e123inf: f32,
}

// Vector: the coefficients of e1, e2, e3, einf.
struct g123inf_Vector {
    e1: f32,
    e2: f32,
    e3: f32,
    einf: f32,
}

// Bivector: the coefficients of e12, e13, e23, e1inf, e2inf, e3inf.
struct g123inf_Bivector {
    e12: f32,
    e13: f32,
    e23: f32,
    e1inf: f32,
    e2inf: f32,
    e3inf: f32,
}

// The odd part of the algebra, declared automatically: some product of the declared types lands here.
// Odd: the coefficients of e1, e2, e3, einf, e123, e12inf, e13inf, e23inf.
struct g123inf_Odd {
    e1: f32,
    e2: f32,
    e3: f32,
    einf: f32,
    e123: f32,
    e12inf: f32,
    e13inf: f32,
    e23inf: f32,
}

// (sinc t, (cos t - sinc t) / t^2, cos t) from t^2 >= 0 (series below t = 1e-3).
fn g123inf_exp_factors(theta2: f32) -> vec3<f32> {
    let theta = sqrt(theta2);
    if (theta < 0.001f) {
        let t4 = theta2 * theta2;
        return vec3<f32>((1.0f - 0.16666667f * theta2) + 0.008333334f * t4, ((-0.33333334f) + 0.033333335f * theta2) - 0.0011904762f * t4, (1.0f - 0.5f * theta2) + 0.041666668f * t4);
    } else {
        let si = sin(theta);
        let co = cos(theta);
        let inv = 1.0f / theta;
        let sinc = si * inv;
        return vec3<f32>(sinc, (co - sinc) * (inv * inv), co);
    }
}

// (t / sin t, (t cos t - sin t) / sin^3 t, 0) from sin t >= 0 and cos t, t = atan2 (series below t = 1e-3).
fn g123inf_log_factors(si: f32, co: f32) -> vec3<f32> {
    let theta = atan2(si, co);
    if (theta < 0.001f) {
        let t2 = theta * theta;
        let t4 = t2 * t2;
        return vec3<f32>((1.0f + 0.16666667f * t2) + 0.019444445f * t4, ((-0.33333334f) - 0.13333334f * t2) - 0.031746034f * t4, 0.0f);
    } else {
        let r = 1.0f / si;
        let r2 = r * r;
        return vec3<f32>(theta * r, (theta * co - si) * (r2 * r), 0.0f);
    }
}

// `gp` of a Motor and a Motor.
fn g123inf_motor_gp_motor(a: g123inf_Motor, b: g123inf_Motor) -> g123inf_Motor {
    let t0 = a.scalar * b.scalar;
    let t1 = a.scalar * b.e12;
    let t2 = a.scalar * b.e13;
    let t3 = a.scalar * b.e23;
    let t4 = a.scalar * b.e1inf;
    let t5 = a.scalar * b.e2inf;
    let t6 = a.scalar * b.e3inf;
    let t7 = a.scalar * b.e123inf;
    let t8 = a.e12 * b.scalar;
    let t9 = a.e12 * b.e12;
    let t10 = a.e12 * b.e13;
    let t11 = a.e12 * b.e23;
    let t12 = a.e12 * b.e1inf;
    let t13 = a.e12 * b.e2inf;
    let t14 = a.e12 * b.e3inf;
    let t15 = a.e12 * b.e123inf;
    let t16 = a.e13 * b.scalar;
    let t17 = a.e13 * b.e12;
    let t18 = a.e13 * b.e13;
    let t19 = a.e13 * b.e23;
    let t20 = a.e13 * b.e1inf;
    let t21 = a.e13 * b.e2inf;
    let t22 = a.e13 * b.e3inf;
    let t23 = a.e13 * b.e123inf;
    let t24 = a.e23 * b.scalar;
    let t25 = a.e23 * b.e12;
    let t26 = a.e23 * b.e13;
    let t27 = a.e23 * b.e23;
    let t28 = a.e23 * b.e1inf;
    let t29 = a.e23 * b.e2inf;
    let t30 = a.e23 * b.e3inf;
    let t31 = a.e23 * b.e123inf;
    let t32 = a.e1inf * b.scalar;
    let t33 = a.e1inf * b.e12;
    let t34 = a.e1inf * b.e13;
    let t35 = a.e1inf * b.e23;
    let t36 = a.e2inf * b.scalar;
    let t37 = a.e2inf * b.e12;
    let t38 = a.e2inf * b.e13;
    let t39 = a.e2inf * b.e23;
    let t40 = a.e3inf * b.scalar;
    let t41 = a.e3inf * b.e12;
    let t42 = a.e3inf * b.e13;
    let t43 = a.e3inf * b.e23;
    let t44 = a.e123inf * b.scalar;
    let t45 = a.e123inf * b.e12;
    let t46 = a.e123inf * b.e13;
    let t47 = a.e123inf * b.e23;
    return g123inf_Motor(
        ((t0 - t9) - t18) - t27,
        ((t1 + t8) + t26) - t19,
        ((t2 + t11) + t16) - t25,
        ((t3 + t17) + t24) - t10,
        ((((((t4 + t13) + t22) - t31) + t32) - t37) - t42) - t47,
        ((((((t5 + t23) + t30) - t12) + t33) + t36) + t46) - t43,
        ((((((t6 - t15) - t20) - t29) + t34) + t39) + t40) - t45,
        ((((((t7 + t14) + t28) - t21) + t35) + t41) + t44) - t38,
    );
}

// `gp` of a Motor and a Vector.
fn g123inf_motor_gp_vector(a: g123inf_Motor, b: g123inf_Vector) -> g123inf_Odd {
    let t0 = a.scalar * b.e1;
    let t1 = a.scalar * b.e2;
    let t2 = a.scalar * b.e3;
    let t3 = a.scalar * b.einf;
    let t4 = a.e12 * b.e1;
    let t5 = a.e12 * b.e2;
    let t6 = a.e12 * b.e3;
    let t7 = a.e12 * b.einf;
    let t8 = a.e13 * b.e1;
    let t9 = a.e13 * b.e2;
    let t10 = a.e13 * b.e3;
    let t11 = a.e13 * b.einf;
    let t12 = a.e23 * b.e1;
    let t13 = a.e23 * b.e2;
    let t14 = a.e23 * b.e3;
    let t15 = a.e23 * b.einf;
    let t16 = a.e1inf * b.e1;
    let t17 = a.e1inf * b.e2;
    let t18 = a.e1inf * b.e3;
    let t19 = a.e2inf * b.e1;
    let t20 = a.e2inf * b.e2;
    let t21 = a.e2inf * b.e3;
    let t22 = a.e3inf * b.e1;
    let t23 = a.e3inf * b.e2;
    let t24 = a.e3inf * b.e3;
    let t25 = a.e123inf * b.e1;
    let t26 = a.e123inf * b.e2;
    let t27 = a.e123inf * b.e3;
    return g123inf_Odd(
        (t0 + t5) + t10,
        (t1 - t4) + t14,
        (t2 - t8) - t13,
        ((t3 - t16) - t20) - t24,
        (t6 - t9) + t12,
        ((t7 - t17) + t19) - t27,
        ((t11 - t18) + t22) + t26,
        ((t15 - t21) + t23) - t25,
    );
}

// `gp` of a Motor and a Bivector.
fn g123inf_motor_gp_bivector(a: g123inf_Motor, b: g123inf_Bivector) -> g123inf_Motor {
    let t0 = a.scalar * b.e12;
    let t1 = a.scalar * b.e13;
    let t2 = a.scalar * b.e23;
    let t3 = a.scalar * b.e1inf;
    let t4 = a.scalar * b.e2inf;
    let t5 = a.scalar * b.e3inf;
    let t6 = a.e12 * b.e12;
    let t7 = a.e12 * b.e13;
    let t8 = a.e12 * b.e23;
    let t9 = a.e12 * b.e1inf;
    let t10 = a.e12 * b.e2inf;
    let t11 = a.e12 * b.e3inf;
    let t12 = a.e13 * b.e12;
    let t13 = a.e13 * b.e13;
    let t14 = a.e13 * b.e23;
    let t15 = a.e13 * b.e1inf;
    let t16 = a.e13 * b.e2inf;
    let t17 = a.e13 * b.e3inf;
    let t18 = a.e23 * b.e12;
    let t19 = a.e23 * b.e13;
    let t20 = a.e23 * b.e23;
    let t21 = a.e23 * b.e1inf;
    let t22 = a.e23 * b.e2inf;
    let t23 = a.e23 * b.e3inf;
    let t24 = a.e1inf * b.e12;
    let t25 = a.e1inf * b.e13;
    let t26 = a.e1inf * b.e23;
    let t27 = a.e2inf * b.e12;
    let t28 = a.e2inf * b.e13;
    let t29 = a.e2inf * b.e23;
    let t30 = a.e3inf * b.e12;
    let t31 = a.e3inf * b.e13;
    let t32 = a.e3inf * b.e23;
    let t33 = a.e123inf * b.e12;
    let t34 = a.e123inf * b.e13;
    let t35 = a.e123inf * b.e23;
    return g123inf_Motor(
        ((-t6) - t13) - t20,
        (t0 - t14) + t19,
        (t1 + t8) - t18,
        (t2 - t7) + t12,
        (((t3 + t10) + t17) - t27) - (t31 + t35),
        (((t4 - t9) + t23) + t24) - (t32 - t34),
        (((t5 - t15) - t22) + t25) + (t29 - t33),
        (((t11 - t16) + t21) + t26) - (t28 - t30),
    );
}

// `gp` of a Vector and a Motor.
fn g123inf_vector_gp_motor(a: g123inf_Vector, b: g123inf_Motor) -> g123inf_Odd {
    let t0 = a.e1 * b.scalar;
    let t1 = a.e1 * b.e12;
    let t2 = a.e1 * b.e13;
    let t3 = a.e1 * b.e23;
    let t4 = a.e1 * b.e1inf;
    let t5 = a.e1 * b.e2inf;
    let t6 = a.e1 * b.e3inf;
    let t7 = a.e1 * b.e123inf;
    let t8 = a.e2 * b.scalar;
    let t9 = a.e2 * b.e12;
    let t10 = a.e2 * b.e13;
    let t11 = a.e2 * b.e23;
    let t12 = a.e2 * b.e1inf;
    let t13 = a.e2 * b.e2inf;
    let t14 = a.e2 * b.e3inf;
    let t15 = a.e2 * b.e123inf;
    let t16 = a.e3 * b.scalar;
    let t17 = a.e3 * b.e12;
    let t18 = a.e3 * b.e13;
    let t19 = a.e3 * b.e23;
    let t20 = a.e3 * b.e1inf;
    let t21 = a.e3 * b.e2inf;
    let t22 = a.e3 * b.e3inf;
    let t23 = a.e3 * b.e123inf;
    let t24 = a.einf * b.scalar;
    let t25 = a.einf * b.e12;
    let t26 = a.einf * b.e13;
    let t27 = a.einf * b.e23;
    return g123inf_Odd(
        (t0 - t9) - t18,
        (t1 + t8) - t19,
        (t2 + t11) + t16,
        ((t4 + t13) + t22) + t24,
        (t3 - t10) + t17,
        ((t5 - t12) + t23) + t25,
        ((t6 - t15) - t20) + t26,
        ((t7 + t14) - t21) + t27,
    );
}

// `gp` of a Vector and a Vector.
fn g123inf_vector_gp_vector(a: g123inf_Vector, b: g123inf_Vector) -> g123inf_Motor {
    let t0 = a.e1 * b.e1;
    let t1 = a.e1 * b.e2;
    let t2 = a.e1 * b.e3;
    let t3 = a.e1 * b.einf;
    let t4 = a.e2 * b.e1;
    let t5 = a.e2 * b.e2;
    let t6 = a.e2 * b.e3;
    let t7 = a.e2 * b.einf;
    let t8 = a.e3 * b.e1;
    let t9 = a.e3 * b.e2;
    let t10 = a.e3 * b.e3;
    let t11 = a.e3 * b.einf;
    let t12 = a.einf * b.e1;
    let t13 = a.einf * b.e2;
    let t14 = a.einf * b.e3;
    return g123inf_Motor(
        (t0 + t5) + t10,
        t1 - t4,
        t2 - t8,
        t6 - t9,
        t3 - t12,
        t7 - t13,
        t11 - t14,
        0.0f,
    );
}

// `gp` of a Vector and a Bivector.
fn g123inf_vector_gp_bivector(a: g123inf_Vector, b: g123inf_Bivector) -> g123inf_Odd {
    let t0 = a.e1 * b.e12;
    let t1 = a.e1 * b.e13;
    let t2 = a.e1 * b.e23;
    let t3 = a.e1 * b.e1inf;
    let t4 = a.e1 * b.e2inf;
    let t5 = a.e1 * b.e3inf;
    let t6 = a.e2 * b.e12;
    let t7 = a.e2 * b.e13;
    let t8 = a.e2 * b.e23;
    let t9 = a.e2 * b.e1inf;
    let t10 = a.e2 * b.e2inf;
    let t11 = a.e2 * b.e3inf;
    let t12 = a.e3 * b.e12;
    let t13 = a.e3 * b.e13;
    let t14 = a.e3 * b.e23;
    let t15 = a.e3 * b.e1inf;
    let t16 = a.e3 * b.e2inf;
    let t17 = a.e3 * b.e3inf;
    let t18 = a.einf * b.e12;
    let t19 = a.einf * b.e13;
    let t20 = a.einf * b.e23;
    return g123inf_Odd(
        (-t6) - t13,
        t0 - t14,
        t1 + t8,
        (t3 + t10) + t17,
        (t2 - t7) + t12,
        (t4 - t9) + t18,
        (t5 - t15) + t19,
        (t11 - t16) + t20,
    );
}

// `gp` of a Bivector and a Motor.
fn g123inf_bivector_gp_motor(a: g123inf_Bivector, b: g123inf_Motor) -> g123inf_Motor {
    let t0 = a.e12 * b.scalar;
    let t1 = a.e12 * b.e12;
    let t2 = a.e12 * b.e13;
    let t3 = a.e12 * b.e23;
    let t4 = a.e12 * b.e1inf;
    let t5 = a.e12 * b.e2inf;
    let t6 = a.e12 * b.e3inf;
    let t7 = a.e12 * b.e123inf;
    let t8 = a.e13 * b.scalar;
    let t9 = a.e13 * b.e12;
    let t10 = a.e13 * b.e13;
    let t11 = a.e13 * b.e23;
    let t12 = a.e13 * b.e1inf;
    let t13 = a.e13 * b.e2inf;
    let t14 = a.e13 * b.e3inf;
    let t15 = a.e13 * b.e123inf;
    let t16 = a.e23 * b.scalar;
    let t17 = a.e23 * b.e12;
    let t18 = a.e23 * b.e13;
    let t19 = a.e23 * b.e23;
    let t20 = a.e23 * b.e1inf;
    let t21 = a.e23 * b.e2inf;
    let t22 = a.e23 * b.e3inf;
    let t23 = a.e23 * b.e123inf;
    let t24 = a.e1inf * b.scalar;
    let t25 = a.e1inf * b.e12;
    let t26 = a.e1inf * b.e13;
    let t27 = a.e1inf * b.e23;
    let t28 = a.e2inf * b.scalar;
    let t29 = a.e2inf * b.e12;
    let t30 = a.e2inf * b.e13;
    let t31 = a.e2inf * b.e23;
    let t32 = a.e3inf * b.scalar;
    let t33 = a.e3inf * b.e12;
    let t34 = a.e3inf * b.e13;
    let t35 = a.e3inf * b.e23;
    return g123inf_Motor(
        ((-t1) - t10) - t19,
        (t0 - t11) + t18,
        (t3 + t8) - t17,
        (t9 - t2) + t16,
        (((t5 + t14) - t23) + t24) - (t29 + t34),
        (((t15 - t4) + t22) + t25) + (t28 - t35),
        (((t26 - t12) - t21) - t7) + (t31 + t32),
        (((t6 - t13) + t20) + t27) - (t30 - t33),
    );
}

// `gp` of a Bivector and a Vector.
fn g123inf_bivector_gp_vector(a: g123inf_Bivector, b: g123inf_Vector) -> g123inf_Odd {
    let t0 = a.e12 * b.e1;
    let t1 = a.e12 * b.e2;
    let t2 = a.e12 * b.e3;
    let t3 = a.e12 * b.einf;
    let t4 = a.e13 * b.e1;
    let t5 = a.e13 * b.e2;
    let t6 = a.e13 * b.e3;
    let t7 = a.e13 * b.einf;
    let t8 = a.e23 * b.e1;
    let t9 = a.e23 * b.e2;
    let t10 = a.e23 * b.e3;
    let t11 = a.e23 * b.einf;
    let t12 = a.e1inf * b.e1;
    let t13 = a.e1inf * b.e2;
    let t14 = a.e1inf * b.e3;
    let t15 = a.e2inf * b.e1;
    let t16 = a.e2inf * b.e2;
    let t17 = a.e2inf * b.e3;
    let t18 = a.e3inf * b.e1;
    let t19 = a.e3inf * b.e2;
    let t20 = a.e3inf * b.e3;
    return g123inf_Odd(
        t1 + t6,
        t10 - t0,
        (-t4) - t9,
        ((-t12) - t16) - t20,
        (t2 - t5) + t8,
        (t3 - t13) + t15,
        (t7 - t14) + t18,
        (t11 - t17) + t19,
    );
}

// `gp` of a Bivector and a Bivector.
fn g123inf_bivector_gp_bivector(a: g123inf_Bivector, b: g123inf_Bivector) -> g123inf_Motor {
    let t0 = a.e12 * b.e12;
    let t1 = a.e12 * b.e13;
    let t2 = a.e12 * b.e23;
    let t3 = a.e12 * b.e1inf;
    let t4 = a.e12 * b.e2inf;
    let t5 = a.e12 * b.e3inf;
    let t6 = a.e13 * b.e12;
    let t7 = a.e13 * b.e13;
    let t8 = a.e13 * b.e23;
    let t9 = a.e13 * b.e1inf;
    let t10 = a.e13 * b.e2inf;
    let t11 = a.e13 * b.e3inf;
    let t12 = a.e23 * b.e12;
    let t13 = a.e23 * b.e13;
    let t14 = a.e23 * b.e23;
    let t15 = a.e23 * b.e1inf;
    let t16 = a.e23 * b.e2inf;
    let t17 = a.e23 * b.e3inf;
    let t18 = a.e1inf * b.e12;
    let t19 = a.e1inf * b.e13;
    let t20 = a.e1inf * b.e23;
    let t21 = a.e2inf * b.e12;
    let t22 = a.e2inf * b.e13;
    let t23 = a.e2inf * b.e23;
    let t24 = a.e3inf * b.e12;
    let t25 = a.e3inf * b.e13;
    let t26 = a.e3inf * b.e23;
    return g123inf_Motor(
        ((-t0) - t7) - t14,
        t13 - t8,
        t2 - t12,
        t6 - t1,
        ((t4 + t11) - t21) - t25,
        ((t17 - t3) + t18) - t26,
        ((t19 - t16) - t9) + t23,
        (((t5 - t10) + t15) + t20) - (t22 - t24),
    );
}

// The reverse of a Motor.
fn g123inf_motor_reverse(x: g123inf_Motor) -> g123inf_Motor {
    return g123inf_Motor(
        x.scalar,
        -x.e12,
        -x.e13,
        -x.e23,
        -x.e1inf,
        -x.e2inf,
        -x.e3inf,
        x.e123inf,
    );
}

// The squared norm <x rev(x)>_0 of a Motor (may be negative or zero).
fn g123inf_motor_norm_squared(x: g123inf_Motor) -> f32 {
    let t0 = x.scalar * x.scalar;
    let t1 = x.e12 * x.e12;
    let t2 = x.e13 * x.e13;
    let t3 = x.e23 * x.e23;
    return ((t0 + t1) + t2) + t3;
}

// The reverse of a Vector.
fn g123inf_vector_reverse(x: g123inf_Vector) -> g123inf_Vector {
    return g123inf_Vector(
        x.e1,
        x.e2,
        x.e3,
        x.einf,
    );
}

// The squared norm <x rev(x)>_0 of a Vector (may be negative or zero).
fn g123inf_vector_norm_squared(x: g123inf_Vector) -> f32 {
    let t0 = x.e1 * x.e1;
    let t1 = x.e2 * x.e2;
    let t2 = x.e3 * x.e3;
    return (t0 + t1) + t2;
}

// The reverse of a Bivector.
fn g123inf_bivector_reverse(x: g123inf_Bivector) -> g123inf_Bivector {
    return g123inf_Bivector(
        -x.e12,
        -x.e13,
        -x.e23,
        -x.e1inf,
        -x.e2inf,
        -x.e3inf,
    );
}

// The squared norm <x rev(x)>_0 of a Bivector (may be negative or zero).
fn g123inf_bivector_norm_squared(x: g123inf_Bivector) -> f32 {
    let t0 = x.e12 * x.e12;
    let t1 = x.e13 * x.e13;
    let t2 = x.e23 * x.e23;
    return (t0 + t1) + t2;
}

// rev(S) x S for a Motor S and a Motor x, in one fused kernel.
fn g123inf_motor_sandwich_motor(s: g123inf_Motor, x: g123inf_Motor) -> g123inf_Motor {
    let t0 = ((s.scalar * x.scalar) + (s.e12 * x.e12)) + ((s.e13 * x.e13) + (s.e23 * x.e23));
    let t1 = ((s.scalar * x.e12) + (s.e13 * x.e23)) - ((s.e12 * x.scalar) + (s.e23 * x.e13));
    let t2 = ((s.scalar * x.e13) + (s.e23 * x.e12)) - ((s.e12 * x.e23) + (s.e13 * x.scalar));
    let t3 = ((s.scalar * x.e23) + (s.e12 * x.e13)) - ((s.e13 * x.e12) + (s.e23 * x.scalar));
    let t4 = (((s.scalar * x.e1inf) + (s.e23 * x.e123inf)) + ((s.e2inf * x.e12) + (s.e3inf * x.e13))) - (((s.e12 * x.e2inf) + (s.e13 * x.e3inf)) + ((s.e1inf * x.scalar) + (s.e123inf * x.e23)));
    let t5 = (((s.scalar * x.e2inf) + (s.e12 * x.e1inf)) + ((s.e3inf * x.e23) + (s.e123inf * x.e13))) - (((s.e13 * x.e123inf) + (s.e23 * x.e3inf)) + ((s.e1inf * x.e12) + (s.e2inf * x.scalar)));
    let t6 = (((s.scalar * x.e3inf) + (s.e12 * x.e123inf)) + ((s.e13 * x.e1inf) + (s.e23 * x.e2inf))) - (((s.e1inf * x.e13) + (s.e2inf * x.e23)) + ((s.e3inf * x.scalar) + (s.e123inf * x.e12)));
    let t7 = (((s.scalar * x.e123inf) + (s.e13 * x.e2inf)) + ((s.e2inf * x.e13) + (s.e123inf * x.scalar))) - (((s.e12 * x.e3inf) + (s.e23 * x.e1inf)) + ((s.e1inf * x.e23) + (s.e3inf * x.e12)));
    return g123inf_Motor(
        ((t0 * s.scalar) - (t1 * s.e12)) - ((t2 * s.e13) + (t3 * s.e23)),
        ((t1 * s.scalar) + (t0 * s.e12)) + ((t3 * s.e13) - (t2 * s.e23)),
        ((t2 * s.scalar) - (t3 * s.e12)) + ((t0 * s.e13) + (t1 * s.e23)),
        ((t3 * s.scalar) + (t2 * s.e12)) - ((t1 * s.e13) - (t0 * s.e23)),
        (((t4 * s.scalar) - (t5 * s.e12)) - ((t6 * s.e13) + (t7 * s.e23))) + (((t0 * s.e1inf) + (t1 * s.e2inf)) + ((t2 * s.e3inf) - (t3 * s.e123inf))),
        (((t5 * s.scalar) + (t4 * s.e12)) + ((t7 * s.e13) - (t6 * s.e23))) - (((t1 * s.e1inf) - (t0 * s.e2inf)) - ((t3 * s.e3inf) + (t2 * s.e123inf))),
        (((t6 * s.scalar) - (t7 * s.e12)) + ((t4 * s.e13) + (t5 * s.e23))) - (((t2 * s.e1inf) + (t3 * s.e2inf)) - ((t0 * s.e3inf) - (t1 * s.e123inf))),
        (((t7 * s.scalar) + (t6 * s.e12)) - ((t5 * s.e13) - (t4 * s.e23))) + (((t3 * s.e1inf) - (t2 * s.e2inf)) + ((t1 * s.e3inf) + (t0 * s.e123inf))),
    );
}

// rev(S) x S for a Motor S and a Vector x, in one fused kernel.
fn g123inf_motor_sandwich_vector(s: g123inf_Motor, x: g123inf_Vector) -> g123inf_Vector {
    let t0 = -((s.e12 * x.e2) + (s.e13 * x.e3));
    let t1 = (s.e12 * x.e1) - (s.e23 * x.e3);
    let t2 = (s.e13 * x.e1) + (s.e23 * x.e2);
    let t3 = (s.e1inf * x.e1) + ((s.e2inf * x.e2) + (s.e3inf * x.e3));
    let t4 = -(s.e123inf * x.e3);
    let t5 = s.e123inf * x.e2;
    let t6 = -(s.e123inf * x.e1);
    let t7 = ((s.scalar * s.scalar) + (s.e12 * s.e12)) + ((s.e13 * s.e13) + (s.e23 * s.e23));
    let t8 = (t0 * s.scalar) - ((t1 * s.e12) + (t2 * s.e13));
    let t9 = (t1 * s.scalar) + ((t0 * s.e12) - (t2 * s.e23));
    let t10 = (t2 * s.scalar) + ((t0 * s.e13) + (t1 * s.e23));
    let t11 = ((t3 * s.scalar) - ((t4 * s.e12) + (t5 * s.e13))) - (((t6 * s.e23) - (t0 * s.e1inf)) - ((t1 * s.e2inf) + (t2 * s.e3inf)));
    return g123inf_Vector(
        (t7 * x.e1) + (t8 + t8),
        (t7 * x.e2) + (t9 + t9),
        (t7 * x.e3) + (t10 + t10),
        (t7 * x.einf) + (t11 + t11),
    );
}

// rev(S) x S for a Motor S and a Bivector x, in one fused kernel.
fn g123inf_motor_sandwich_bivector(s: g123inf_Motor, x: g123inf_Bivector) -> g123inf_Bivector {
    let t0 = (s.e12 * x.e12) + ((s.e13 * x.e13) + (s.e23 * x.e23));
    let t1 = (s.scalar * x.e12) + ((s.e13 * x.e23) - (s.e23 * x.e13));
    let t2 = (s.scalar * x.e13) + ((s.e23 * x.e12) - (s.e12 * x.e23));
    let t3 = (s.scalar * x.e23) + ((s.e12 * x.e13) - (s.e13 * x.e12));
    let t4 = ((s.scalar * x.e1inf) + ((s.e2inf * x.e12) + (s.e3inf * x.e13))) - ((s.e12 * x.e2inf) + ((s.e13 * x.e3inf) + (s.e123inf * x.e23)));
    let t5 = ((s.scalar * x.e2inf) + ((s.e12 * x.e1inf) + (s.e3inf * x.e23))) + ((s.e123inf * x.e13) - ((s.e23 * x.e3inf) + (s.e1inf * x.e12)));
    let t6 = ((s.scalar * x.e3inf) + ((s.e13 * x.e1inf) + (s.e23 * x.e2inf))) - ((s.e1inf * x.e13) + ((s.e2inf * x.e23) + (s.e123inf * x.e12)));
    let t7 = ((s.e13 * x.e2inf) + ((s.e2inf * x.e13) - (s.e12 * x.e3inf))) - ((s.e23 * x.e1inf) + ((s.e1inf * x.e23) + (s.e3inf * x.e12)));
    return g123inf_Bivector(
        ((t1 * s.scalar) + (t0 * s.e12)) + ((t3 * s.e13) - (t2 * s.e23)),
        ((t2 * s.scalar) - (t3 * s.e12)) + ((t0 * s.e13) + (t1 * s.e23)),
        ((t3 * s.scalar) + (t2 * s.e12)) - ((t1 * s.e13) - (t0 * s.e23)),
        (((t4 * s.scalar) - (t5 * s.e12)) - ((t6 * s.e13) + (t7 * s.e23))) + (((t0 * s.e1inf) + (t1 * s.e2inf)) + ((t2 * s.e3inf) - (t3 * s.e123inf))),
        (((t5 * s.scalar) + (t4 * s.e12)) + ((t7 * s.e13) - (t6 * s.e23))) - (((t1 * s.e1inf) - (t0 * s.e2inf)) - ((t3 * s.e3inf) + (t2 * s.e123inf))),
        (((t6 * s.scalar) - (t7 * s.e12)) + ((t4 * s.e13) + (t5 * s.e23))) - (((t2 * s.e1inf) + (t3 * s.e2inf)) - ((t0 * s.e3inf) - (t1 * s.e123inf))),
    );
}

// rev(S) x S for a Vector S and a Motor x, in one fused kernel.
fn g123inf_vector_sandwich_motor(s: g123inf_Vector, x: g123inf_Motor) -> g123inf_Motor {
    let t0 = (s.e1 * x.scalar) - ((s.e2 * x.e12) + (s.e3 * x.e13));
    let t1 = (s.e1 * x.e12) + ((s.e2 * x.scalar) - (s.e3 * x.e23));
    let t2 = (s.e1 * x.e13) + ((s.e2 * x.e23) + (s.e3 * x.scalar));
    let t3 = (s.e1 * x.e23) + ((s.e3 * x.e12) - (s.e2 * x.e13));
    let t4 = ((s.e1 * x.e1inf) + (s.e2 * x.e2inf)) + ((s.e3 * x.e3inf) + (s.einf * x.scalar));
    let t5 = ((s.e1 * x.e2inf) + (s.e3 * x.e123inf)) + ((s.einf * x.e12) - (s.e2 * x.e1inf));
    let t6 = ((s.e1 * x.e3inf) + (s.einf * x.e13)) - ((s.e2 * x.e123inf) + (s.e3 * x.e1inf));
    let t7 = ((s.e1 * x.e123inf) + (s.e2 * x.e3inf)) + ((s.einf * x.e23) - (s.e3 * x.e2inf));
    return g123inf_Motor(
        (t0 * s.e1) + ((t1 * s.e2) + (t2 * s.e3)),
        (t0 * s.e2) - ((t1 * s.e1) - (t3 * s.e3)),
        (t0 * s.e3) - ((t2 * s.e1) + (t3 * s.e2)),
        (t3 * s.e1) - ((t2 * s.e2) - (t1 * s.e3)),
        ((t0 * s.einf) - (t4 * s.e1)) - ((t5 * s.e2) + (t6 * s.e3)),
        ((t5 * s.e1) - (t4 * s.e2)) - ((t7 * s.e3) - (t1 * s.einf)),
        ((t6 * s.e1) + (t7 * s.e2)) - ((t4 * s.e3) - (t2 * s.einf)),
        ((t6 * s.e2) - (t7 * s.e1)) - ((t5 * s.e3) - (t3 * s.einf)),
    );
}

// rev(S) x S for a Vector S and a Vector x, in one fused kernel.
fn g123inf_vector_sandwich_vector(s: g123inf_Vector, x: g123inf_Vector) -> g123inf_Vector {
    let t0 = (s.e1 * x.e1) + ((s.e2 * x.e2) + (s.e3 * x.e3));
    let t1 = (s.e1 * x.e2) - (s.e2 * x.e1);
    let t2 = (s.e1 * x.e3) - (s.e3 * x.e1);
    let t3 = (s.e2 * x.e3) - (s.e3 * x.e2);
    let t4 = (s.e1 * x.einf) - (s.einf * x.e1);
    let t5 = (s.e2 * x.einf) - (s.einf * x.e2);
    let t6 = (s.e3 * x.einf) - (s.einf * x.e3);
    return g123inf_Vector(
        (t0 * s.e1) + ((t1 * s.e2) + (t2 * s.e3)),
        (t0 * s.e2) - ((t1 * s.e1) - (t3 * s.e3)),
        (t0 * s.e3) - ((t2 * s.e1) + (t3 * s.e2)),
        ((t0 * s.einf) - (t4 * s.e1)) - ((t5 * s.e2) + (t6 * s.e3)),
    );
}

// rev(S) x S for a Vector S and a Bivector x, in one fused kernel.
fn g123inf_vector_sandwich_bivector(s: g123inf_Vector, x: g123inf_Bivector) -> g123inf_Bivector {
    let t0 = -((s.e2 * x.e12) + (s.e3 * x.e13));
    let t1 = (s.e1 * x.e12) - (s.e3 * x.e23);
    let t2 = (s.e1 * x.e13) + (s.e2 * x.e23);
    let t3 = (s.e1 * x.e1inf) + ((s.e2 * x.e2inf) + (s.e3 * x.e3inf));
    let t4 = (s.e1 * s.e1) + ((s.e2 * s.e2) + (s.e3 * s.e3));
    let t5 = (t0 * s.e2) - (t1 * s.e1);
    let t6 = (t0 * s.e3) - (t2 * s.e1);
    let t7 = (t1 * s.e3) - (t2 * s.e2);
    let t8 = (t0 * s.einf) - (t3 * s.e1);
    let t9 = (t1 * s.einf) - (t3 * s.e2);
    let t10 = (t2 * s.einf) - (t3 * s.e3);
    return g123inf_Bivector(
        (t4 * x.e12) + (t5 + t5),
        (t4 * x.e13) + (t6 + t6),
        (t4 * x.e23) + (t7 + t7),
        (t4 * x.e1inf) + (t8 + t8),
        (t4 * x.e2inf) + (t9 + t9),
        (t4 * x.e3inf) + (t10 + t10),
    );
}

// rev(S) x S for a Bivector S and a Motor x, in one fused kernel.
fn g123inf_bivector_sandwich_motor(s: g123inf_Bivector, x: g123inf_Motor) -> g123inf_Motor {
    let t0 = (s.e12 * x.e12) + ((s.e13 * x.e13) + (s.e23 * x.e23));
    let t1 = (s.e13 * x.e23) - ((s.e12 * x.scalar) + (s.e23 * x.e13));
    let t2 = (s.e23 * x.e12) - ((s.e12 * x.e23) + (s.e13 * x.scalar));
    let t3 = (s.e12 * x.e13) - ((s.e13 * x.e12) + (s.e23 * x.scalar));
    let t4 = ((s.e23 * x.e123inf) + ((s.e2inf * x.e12) + (s.e3inf * x.e13))) - ((s.e12 * x.e2inf) + ((s.e13 * x.e3inf) + (s.e1inf * x.scalar)));
    let t5 = ((s.e12 * x.e1inf) + ((s.e3inf * x.e23) - (s.e13 * x.e123inf))) - ((s.e23 * x.e3inf) + ((s.e1inf * x.e12) + (s.e2inf * x.scalar)));
    let t6 = ((s.e12 * x.e123inf) + ((s.e13 * x.e1inf) + (s.e23 * x.e2inf))) - ((s.e1inf * x.e13) + ((s.e2inf * x.e23) + (s.e3inf * x.scalar)));
    let t7 = ((s.e13 * x.e2inf) + ((s.e2inf * x.e13) - (s.e12 * x.e3inf))) - ((s.e23 * x.e1inf) + ((s.e1inf * x.e23) + (s.e3inf * x.e12)));
    return g123inf_Motor(
        -((t1 * s.e12) + ((t2 * s.e13) + (t3 * s.e23))),
        (t0 * s.e12) + ((t3 * s.e13) - (t2 * s.e23)),
        (t0 * s.e13) - ((t3 * s.e12) - (t1 * s.e23)),
        (t2 * s.e12) - ((t1 * s.e13) - (t0 * s.e23)),
        ((t0 * s.e1inf) - ((t5 * s.e12) + (t6 * s.e13))) - ((t7 * s.e23) - ((t1 * s.e2inf) + (t2 * s.e3inf))),
        ((t4 * s.e12) + ((t7 * s.e13) - (t6 * s.e23))) - ((t1 * s.e1inf) - ((t0 * s.e2inf) + (t3 * s.e3inf))),
        ((t4 * s.e13) - ((t7 * s.e12) - (t5 * s.e23))) - ((t2 * s.e1inf) + ((t3 * s.e2inf) - (t0 * s.e3inf))),
        ((t6 * s.e12) - ((t5 * s.e13) - (t4 * s.e23))) + ((t3 * s.e1inf) - ((t2 * s.e2inf) - (t1 * s.e3inf))),
    );
}

// rev(S) x S for a Bivector S and a Vector x, in one fused kernel.
fn g123inf_bivector_sandwich_vector(s: g123inf_Bivector, x: g123inf_Vector) -> g123inf_Vector {
    let t0 = -((s.e12 * x.e2) + (s.e13 * x.e3));
    let t1 = (s.e12 * x.e1) - (s.e23 * x.e3);
    let t2 = (s.e13 * x.e1) + (s.e23 * x.e2);
    let t3 = (s.e12 * s.e12) + ((s.e13 * s.e13) + (s.e23 * s.e23));
    let t4 = -((t1 * s.e12) + (t2 * s.e13));
    let t5 = (t0 * s.e12) - (t2 * s.e23);
    let t6 = (t0 * s.e13) + (t1 * s.e23);
    let t7 = (t0 * s.e1inf) + ((t1 * s.e2inf) + (t2 * s.e3inf));
    return g123inf_Vector(
        (t3 * x.e1) + (t4 + t4),
        (t3 * x.e2) + (t5 + t5),
        (t3 * x.e3) + (t6 + t6),
        (t3 * x.einf) + (t7 + t7),
    );
}

// rev(S) x S for a Bivector S and a Bivector x, in one fused kernel.
fn g123inf_bivector_sandwich_bivector(s: g123inf_Bivector, x: g123inf_Bivector) -> g123inf_Bivector {
    let t0 = (s.e12 * x.e12) + ((s.e13 * x.e13) + (s.e23 * x.e23));
    let t1 = (s.e13 * x.e23) - (s.e23 * x.e13);
    let t2 = (s.e23 * x.e12) - (s.e12 * x.e23);
    let t3 = (s.e12 * x.e13) - (s.e13 * x.e12);
    let t4 = ((s.e2inf * x.e12) + (s.e3inf * x.e13)) - ((s.e12 * x.e2inf) + (s.e13 * x.e3inf));
    let t5 = ((s.e12 * x.e1inf) + (s.e3inf * x.e23)) - ((s.e23 * x.e3inf) + (s.e1inf * x.e12));
    let t6 = ((s.e13 * x.e1inf) + (s.e23 * x.e2inf)) - ((s.e1inf * x.e13) + (s.e2inf * x.e23));
    let t7 = ((s.e13 * x.e2inf) + ((s.e2inf * x.e13) - (s.e12 * x.e3inf))) - ((s.e23 * x.e1inf) + ((s.e1inf * x.e23) + (s.e3inf * x.e12)));
    return g123inf_Bivector(
        (t0 * s.e12) + ((t3 * s.e13) - (t2 * s.e23)),
        (t0 * s.e13) - ((t3 * s.e12) - (t1 * s.e23)),
        (t2 * s.e12) - ((t1 * s.e13) - (t0 * s.e23)),
        ((t0 * s.e1inf) - ((t5 * s.e12) + (t6 * s.e13))) - ((t7 * s.e23) - ((t1 * s.e2inf) + (t2 * s.e3inf))),
        ((t4 * s.e12) + ((t7 * s.e13) - (t6 * s.e23))) - ((t1 * s.e1inf) - ((t0 * s.e2inf) + (t3 * s.e3inf))),
        ((t4 * s.e13) - ((t7 * s.e12) - (t5 * s.e23))) - ((t2 * s.e1inf) + ((t3 * s.e2inf) - (t0 * s.e3inf))),
    );
}

// rev(S) x S for a unit Motor S (S rev(S) = 1) and a Motor x; not the action otherwise.
fn g123inf_motor_sandwich_unit_motor(s: g123inf_Motor, x: g123inf_Motor) -> g123inf_Motor {
    let t0 = (s.e13 * x.e23) - (s.e23 * x.e13);
    let t1 = -((s.e12 * x.e23) - (s.e23 * x.e12));
    let t2 = (s.e12 * x.e13) - (s.e13 * x.e12);
    let t3 = -(((s.e12 * x.e2inf) + (s.e13 * x.e3inf)) - ((s.e2inf * x.e12) + (s.e3inf * x.e13)));
    let t4 = ((s.e12 * x.e1inf) - (s.e23 * x.e3inf)) - ((s.e1inf * x.e12) - (s.e3inf * x.e23));
    let t5 = ((s.e13 * x.e1inf) + (s.e23 * x.e2inf)) - ((s.e1inf * x.e13) + (s.e2inf * x.e23));
    let t6 = (t0 * s.scalar) - ((t1 * s.e23) - (t2 * s.e13));
    let t7 = (t0 * s.e23) + ((t1 * s.scalar) - (t2 * s.e12));
    let t8 = -((t0 * s.e13) - ((t1 * s.e12) + (t2 * s.scalar)));
    let t9 = ((t0 * s.e2inf) + ((t1 * s.e3inf) - (t2 * s.e123inf))) + ((t3 * s.scalar) - ((t4 * s.e12) + (t5 * s.e13)));
    let t10 = -(((t0 * s.e1inf) - ((t1 * s.e123inf) + (t2 * s.e3inf))) - ((t3 * s.e12) + ((t4 * s.scalar) - (t5 * s.e23))));
    let t11 = -(((t0 * s.e123inf) + ((t1 * s.e1inf) + (t2 * s.e2inf))) - ((t3 * s.e13) + ((t4 * s.e23) + (t5 * s.scalar))));
    return g123inf_Motor(
        x.scalar,
        (x.e12 + t6) + t6,
        (x.e13 + t7) + t7,
        (x.e23 + t8) + t8,
        (x.e1inf + t9) + t9,
        (x.e2inf + t10) + t10,
        (x.e3inf + t11) + t11,
        x.e123inf,
    );
}

// rev(S) x S for a unit Motor S (S rev(S) = 1) and a Vector x; not the action otherwise.
fn g123inf_motor_sandwich_unit_vector(s: g123inf_Motor, x: g123inf_Vector) -> g123inf_Vector {
    let t0 = -((s.e12 * x.e2) + (s.e13 * x.e3));
    let t1 = (s.e12 * x.e1) - (s.e23 * x.e3);
    let t2 = (s.e13 * x.e1) + (s.e23 * x.e2);
    let t3 = (s.e1inf * x.e1) + ((s.e2inf * x.e2) + (s.e3inf * x.e3));
    let t4 = -(s.e123inf * x.e3);
    let t5 = s.e123inf * x.e2;
    let t6 = -(s.e123inf * x.e1);
    let t7 = (t0 * s.scalar) - ((t1 * s.e12) + (t2 * s.e13));
    let t8 = (t0 * s.e12) + ((t1 * s.scalar) - (t2 * s.e23));
    let t9 = (t0 * s.e13) + ((t1 * s.e23) + (t2 * s.scalar));
    let t10 = ((t0 * s.e1inf) + ((t1 * s.e2inf) + (t2 * s.e3inf))) + (((t3 * s.scalar) - (t4 * s.e12)) - ((t5 * s.e13) + (t6 * s.e23)));
    return g123inf_Vector(
        (x.e1 + t7) + t7,
        (x.e2 + t8) + t8,
        (x.e3 + t9) + t9,
        (x.einf + t10) + t10,
    );
}

// rev(S) x S for a unit Motor S (S rev(S) = 1) and a Bivector x; not the action otherwise.
fn g123inf_motor_sandwich_unit_bivector(s: g123inf_Motor, x: g123inf_Bivector) -> g123inf_Bivector {
    let t0 = (s.e13 * x.e23) - (s.e23 * x.e13);
    let t1 = -((s.e12 * x.e23) - (s.e23 * x.e12));
    let t2 = (s.e12 * x.e13) - (s.e13 * x.e12);
    let t3 = -(((s.e12 * x.e2inf) + (s.e13 * x.e3inf)) - ((s.e2inf * x.e12) + (s.e3inf * x.e13)));
    let t4 = ((s.e12 * x.e1inf) - (s.e23 * x.e3inf)) - ((s.e1inf * x.e12) - (s.e3inf * x.e23));
    let t5 = ((s.e13 * x.e1inf) + (s.e23 * x.e2inf)) - ((s.e1inf * x.e13) + (s.e2inf * x.e23));
    let t6 = (t0 * s.scalar) - ((t1 * s.e23) - (t2 * s.e13));
    let t7 = (t0 * s.e23) + ((t1 * s.scalar) - (t2 * s.e12));
    let t8 = -((t0 * s.e13) - ((t1 * s.e12) + (t2 * s.scalar)));
    let t9 = ((t0 * s.e2inf) + ((t1 * s.e3inf) - (t2 * s.e123inf))) + ((t3 * s.scalar) - ((t4 * s.e12) + (t5 * s.e13)));
    let t10 = -(((t0 * s.e1inf) - ((t1 * s.e123inf) + (t2 * s.e3inf))) - ((t3 * s.e12) + ((t4 * s.scalar) - (t5 * s.e23))));
    let t11 = -(((t0 * s.e123inf) + ((t1 * s.e1inf) + (t2 * s.e2inf))) - ((t3 * s.e13) + ((t4 * s.e23) + (t5 * s.scalar))));
    return g123inf_Bivector(
        (x.e12 + t6) + t6,
        (x.e13 + t7) + t7,
        (x.e23 + t8) + t8,
        (x.e1inf + t9) + t9,
        (x.e2inf + t10) + t10,
        (x.e3inf + t11) + t11,
    );
}

// rev(S) x S for a unit Vector S (S rev(S) = 1) and a Motor x; not the action otherwise.
fn g123inf_vector_sandwich_unit_motor(s: g123inf_Vector, x: g123inf_Motor) -> g123inf_Motor {
    let t0 = -((s.e2 * x.e12) + (s.e3 * x.e13));
    let t1 = (s.e1 * x.e12) - (s.e3 * x.e23);
    let t2 = (s.e1 * x.e13) + (s.e2 * x.e23);
    let t3 = (s.e1 * x.e1inf) + ((s.e2 * x.e2inf) + (s.e3 * x.e3inf));
    let t4 = s.e3 * x.e123inf;
    let t5 = -(s.e2 * x.e123inf);
    let t6 = s.e1 * x.e123inf;
    let t7 = (t0 * s.e2) - (t1 * s.e1);
    let t8 = (t0 * s.e3) - (t2 * s.e1);
    let t9 = (t1 * s.e3) - (t2 * s.e2);
    let t10 = ((t0 * s.einf) - (t3 * s.e1)) - ((t4 * s.e2) + (t5 * s.e3));
    let t11 = ((t1 * s.einf) - (t3 * s.e2)) + ((t4 * s.e1) - (t6 * s.e3));
    let t12 = ((t2 * s.einf) - (t3 * s.e3)) + ((t5 * s.e1) + (t6 * s.e2));
    let t13 = -((t4 * s.e3) - ((t5 * s.e2) - (t6 * s.e1)));
    return g123inf_Motor(
        x.scalar,
        (x.e12 + t7) + t7,
        (x.e13 + t8) + t8,
        (x.e23 + t9) + t9,
        (x.e1inf + t10) + t10,
        (x.e2inf + t11) + t11,
        (x.e3inf + t12) + t12,
        (x.e123inf + t13) + t13,
    );
}

// rev(S) x S for a unit Vector S (S rev(S) = 1) and a Vector x; not the action otherwise.
fn g123inf_vector_sandwich_unit_vector(s: g123inf_Vector, x: g123inf_Vector) -> g123inf_Vector {
    let t0 = (s.e1 * x.e2) - (s.e2 * x.e1);
    let t1 = (s.e1 * x.e3) - (s.e3 * x.e1);
    let t2 = (s.e2 * x.e3) - (s.e3 * x.e2);
    let t3 = (s.e1 * x.einf) - (s.einf * x.e1);
    let t4 = (s.e2 * x.einf) - (s.einf * x.e2);
    let t5 = (s.e3 * x.einf) - (s.einf * x.e3);
    let t6 = (t0 * s.e2) + (t1 * s.e3);
    let t7 = -((t0 * s.e1) - (t2 * s.e3));
    let t8 = -((t1 * s.e1) + (t2 * s.e2));
    let t9 = -((t3 * s.e1) + ((t4 * s.e2) + (t5 * s.e3)));
    return g123inf_Vector(
        (x.e1 + t6) + t6,
        (x.e2 + t7) + t7,
        (x.e3 + t8) + t8,
        (x.einf + t9) + t9,
    );
}

// rev(S) x S for a unit Vector S (S rev(S) = 1) and a Bivector x; not the action otherwise.
fn g123inf_vector_sandwich_unit_bivector(s: g123inf_Vector, x: g123inf_Bivector) -> g123inf_Bivector {
    let t0 = -((s.e2 * x.e12) + (s.e3 * x.e13));
    let t1 = (s.e1 * x.e12) - (s.e3 * x.e23);
    let t2 = (s.e1 * x.e13) + (s.e2 * x.e23);
    let t3 = (s.e1 * x.e1inf) + ((s.e2 * x.e2inf) + (s.e3 * x.e3inf));
    let t4 = (t0 * s.e2) - (t1 * s.e1);
    let t5 = (t0 * s.e3) - (t2 * s.e1);
    let t6 = (t1 * s.e3) - (t2 * s.e2);
    let t7 = (t0 * s.einf) - (t3 * s.e1);
    let t8 = (t1 * s.einf) - (t3 * s.e2);
    let t9 = (t2 * s.einf) - (t3 * s.e3);
    return g123inf_Bivector(
        (x.e12 + t4) + t4,
        (x.e13 + t5) + t5,
        (x.e23 + t6) + t6,
        (x.e1inf + t7) + t7,
        (x.e2inf + t8) + t8,
        (x.e3inf + t9) + t9,
    );
}

// rev(S) x S for a unit Bivector S (S rev(S) = 1) and a Motor x; not the action otherwise.
fn g123inf_bivector_sandwich_unit_motor(s: g123inf_Bivector, x: g123inf_Motor) -> g123inf_Motor {
    let t0 = (s.e13 * x.e23) - (s.e23 * x.e13);
    let t1 = -((s.e12 * x.e23) - (s.e23 * x.e12));
    let t2 = (s.e12 * x.e13) - (s.e13 * x.e12);
    let t3 = -(((s.e12 * x.e2inf) + (s.e13 * x.e3inf)) - ((s.e2inf * x.e12) + (s.e3inf * x.e13)));
    let t4 = ((s.e12 * x.e1inf) - (s.e23 * x.e3inf)) - ((s.e1inf * x.e12) - (s.e3inf * x.e23));
    let t5 = ((s.e13 * x.e1inf) + (s.e23 * x.e2inf)) - ((s.e1inf * x.e13) + (s.e2inf * x.e23));
    let t6 = -((t1 * s.e23) - (t2 * s.e13));
    let t7 = (t0 * s.e23) - (t2 * s.e12);
    let t8 = -((t0 * s.e13) - (t1 * s.e12));
    let t9 = ((t0 * s.e2inf) + (t1 * s.e3inf)) - ((t4 * s.e12) + (t5 * s.e13));
    let t10 = -(((t0 * s.e1inf) - (t2 * s.e3inf)) - ((t3 * s.e12) - (t5 * s.e23)));
    let t11 = -(((t1 * s.e1inf) + (t2 * s.e2inf)) - ((t3 * s.e13) + (t4 * s.e23)));
    return g123inf_Motor(
        x.scalar,
        (x.e12 + t6) + t6,
        (x.e13 + t7) + t7,
        (x.e23 + t8) + t8,
        (x.e1inf + t9) + t9,
        (x.e2inf + t10) + t10,
        (x.e3inf + t11) + t11,
        x.e123inf,
    );
}

// rev(S) x S for a unit Bivector S (S rev(S) = 1) and a Vector x; not the action otherwise.
fn g123inf_bivector_sandwich_unit_vector(s: g123inf_Bivector, x: g123inf_Vector) -> g123inf_Vector {
    let t0 = -((s.e12 * x.e2) + (s.e13 * x.e3));
    let t1 = (s.e12 * x.e1) - (s.e23 * x.e3);
    let t2 = (s.e13 * x.e1) + (s.e23 * x.e2);
    let t3 = -((t1 * s.e12) + (t2 * s.e13));
    let t4 = (t0 * s.e12) - (t2 * s.e23);
    let t5 = (t0 * s.e13) + (t1 * s.e23);
    let t6 = (t0 * s.e1inf) + ((t1 * s.e2inf) + (t2 * s.e3inf));
    return g123inf_Vector(
        (x.e1 + t3) + t3,
        (x.e2 + t4) + t4,
        (x.e3 + t5) + t5,
        (x.einf + t6) + t6,
    );
}

// rev(S) x S for a unit Bivector S (S rev(S) = 1) and a Bivector x; not the action otherwise.
fn g123inf_bivector_sandwich_unit_bivector(s: g123inf_Bivector, x: g123inf_Bivector) -> g123inf_Bivector {
    let t0 = (s.e13 * x.e23) - (s.e23 * x.e13);
    let t1 = -((s.e12 * x.e23) - (s.e23 * x.e12));
    let t2 = (s.e12 * x.e13) - (s.e13 * x.e12);
    let t3 = -(((s.e12 * x.e2inf) + (s.e13 * x.e3inf)) - ((s.e2inf * x.e12) + (s.e3inf * x.e13)));
    let t4 = ((s.e12 * x.e1inf) - (s.e23 * x.e3inf)) - ((s.e1inf * x.e12) - (s.e3inf * x.e23));
    let t5 = ((s.e13 * x.e1inf) + (s.e23 * x.e2inf)) - ((s.e1inf * x.e13) + (s.e2inf * x.e23));
    let t6 = -((t1 * s.e23) - (t2 * s.e13));
    let t7 = (t0 * s.e23) - (t2 * s.e12);
    let t8 = -((t0 * s.e13) - (t1 * s.e12));
    let t9 = ((t0 * s.e2inf) + (t1 * s.e3inf)) - ((t4 * s.e12) + (t5 * s.e13));
    let t10 = -(((t0 * s.e1inf) - (t2 * s.e3inf)) - ((t3 * s.e12) - (t5 * s.e23)));
    let t11 = -(((t1 * s.e1inf) + (t2 * s.e2inf)) - ((t3 * s.e13) + (t4 * s.e23)));
    return g123inf_Bivector(
        (x.e12 + t6) + t6,
        (x.e13 + t7) + t7,
        (x.e23 + t8) + t8,
        (x.e1inf + t9) + t9,
        (x.e2inf + t10) + t10,
        (x.e3inf + t11) + t11,
    );
}

// exp of a Bivector: a unit Motor (closed form; non-finite input gives non-finite output).
fn g123inf_bivector_exp(x: g123inf_Bivector) -> g123inf_Motor {
    let t0 = ((x.e12 * x.e12) + (x.e13 * x.e13)) + (x.e23 * x.e23);
    let t1 = g123inf_exp_factors(t0);
    let t2 = ((x.e12 * x.e3inf) - (x.e13 * x.e2inf)) + (x.e23 * x.e1inf);
    let t3 = t2 * t1.y;
    return g123inf_Motor(
        t1.z,
        t1.x * x.e12,
        t1.x * x.e13,
        t1.x * x.e23,
        (t1.x * x.e1inf) + (t3 * x.e23),
        (t1.x * x.e2inf) - (t3 * x.e13),
        (t1.x * x.e3inf) + (t3 * x.e12),
        t2 * t1.x,
    );
}

// log of a unit Motor (m rev(m) = 1): the Bivector B with exp(B) = m, angle in [0, pi); a full turn gives non-finite output.
fn g123inf_motor_log_unit(x: g123inf_Motor) -> g123inf_Bivector {
    let t0 = sqrt(((x.e12 * x.e12) + (x.e13 * x.e13)) + (x.e23 * x.e23));
    let t1 = g123inf_log_factors(t0, x.scalar);
    let t2 = x.e123inf * t1.y;
    return g123inf_Bivector(
        t1.x * x.e12,
        t1.x * x.e13,
        t1.x * x.e23,
        (t1.x * x.e1inf) - (t2 * x.e23),
        (t1.x * x.e2inf) + (t2 * x.e13),
        (t1.x * x.e3inf) - (t2 * x.e12),
    );
}

// m / sqrt(m rev(m)) for a Motor: a unit Motor; a non-positive norm gives non-finite output.
fn g123inf_motor_normalize(x: g123inf_Motor) -> g123inf_Motor {
    let t0 = (x.scalar * x.scalar) - (((-(x.e12 * x.e12)) - (x.e13 * x.e13)) - (x.e23 * x.e23));
    let t1 = 1.0f / t0;
    let t2 = (x.scalar * x.e123inf) - (((x.e12 * x.e3inf) - (x.e13 * x.e2inf)) + (x.e23 * x.e1inf));
    let t3 = sqrt(t1);
    let t4 = (-(t2 * t3)) * t1;
    return g123inf_Motor(
        x.scalar * t3,
        x.e12 * t3,
        x.e13 * t3,
        x.e23 * t3,
        (x.e1inf * t3) + (-(t4 * x.e23)),
        (x.e2inf * t3) + (t4 * x.e13),
        (x.e3inf * t3) + (-(t4 * x.e12)),
        (x.e123inf * t3) + (x.scalar * t4),
    );
}

