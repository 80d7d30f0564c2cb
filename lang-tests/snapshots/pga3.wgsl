// pga3: Motor=even;Point=grade3;Line=grade2; ops gp,apply,apply_unit,reverse,norm_squared,exp,log_unit,normalize
// Motor: the coefficients of scalar, e01, e02, e12, e03, e13, e23, e0123.
struct pga3_Motor {
    scalar: f32,
    e01: f32,
    e02: f32,
    e12: f32,
    e03: f32,
    e13: f32,
    e23: f32,
    e0123: f32,
}

// Point: the coefficients of e012, e013, e023, e123.
struct pga3_Point {
    e012: f32,
    e013: f32,
    e023: f32,
    e123: f32,
}

// Line: the coefficients of e01, e02, e12, e03, e13, e23.
struct pga3_Line {
    e01: f32,
    e02: f32,
    e12: f32,
    e03: f32,
    e13: f32,
    e23: f32,
}

// The odd part of the algebra, declared automatically: some product of the declared types lands here.
// Odd: the coefficients of e0, e1, e2, e3, e012, e013, e023, e123.
struct pga3_Odd {
    e0: f32,
    e1: f32,
    e2: f32,
    e3: f32,
    e012: f32,
    e013: f32,
    e023: f32,
    e123: f32,
}

// (sinc t, (cos t - sinc t) / t^2, cos t) from t^2 >= 0 (series below t = 1e-3).
fn pga3_exp_factors(theta2: f32) -> vec3<f32> {
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
fn pga3_log_factors(si: f32, co: f32) -> vec3<f32> {
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
fn pga3_motor_gp_motor(a: pga3_Motor, b: pga3_Motor) -> pga3_Motor {
    let t0 = a.scalar * b.scalar;
    let t1 = a.scalar * b.e01;
    let t2 = a.scalar * b.e02;
    let t3 = a.scalar * b.e12;
    let t4 = a.scalar * b.e03;
    let t5 = a.scalar * b.e13;
    let t6 = a.scalar * b.e23;
    let t7 = a.scalar * b.e0123;
    let t8 = a.e01 * b.scalar;
    let t9 = a.e01 * b.e12;
    let t10 = a.e01 * b.e13;
    let t11 = a.e01 * b.e23;
    let t12 = a.e02 * b.scalar;
    let t13 = a.e02 * b.e12;
    let t14 = a.e02 * b.e13;
    let t15 = a.e02 * b.e23;
    let t16 = a.e12 * b.scalar;
    let t17 = a.e12 * b.e01;
    let t18 = a.e12 * b.e02;
    let t19 = a.e12 * b.e12;
    let t20 = a.e12 * b.e03;
    let t21 = a.e12 * b.e13;
    let t22 = a.e12 * b.e23;
    let t23 = a.e12 * b.e0123;
    let t24 = a.e03 * b.scalar;
    let t25 = a.e03 * b.e12;
    let t26 = a.e03 * b.e13;
    let t27 = a.e03 * b.e23;
    let t28 = a.e13 * b.scalar;
    let t29 = a.e13 * b.e01;
    let t30 = a.e13 * b.e02;
    let t31 = a.e13 * b.e12;
    let t32 = a.e13 * b.e03;
    let t33 = a.e13 * b.e13;
    let t34 = a.e13 * b.e23;
    let t35 = a.e13 * b.e0123;
    let t36 = a.e23 * b.scalar;
    let t37 = a.e23 * b.e01;
    let t38 = a.e23 * b.e02;
    let t39 = a.e23 * b.e12;
    let t40 = a.e23 * b.e03;
    let t41 = a.e23 * b.e13;
    let t42 = a.e23 * b.e23;
    let t43 = a.e23 * b.e0123;
    let t44 = a.e0123 * b.scalar;
    let t45 = a.e0123 * b.e12;
    let t46 = a.e0123 * b.e13;
    let t47 = a.e0123 * b.e23;
    return pga3_Motor(
        ((t0 - t19) - t33) - t42,
        (((t1 + t8) - t13) + t18) - (((t26 - t32) + t43) + t47),
        (((t2 + t9) + t12) - t17) - (((t27 - t35) - t40) - t46),
        ((t3 + t16) - t34) + t41,
        (((t4 + t10) + t15) - t23) + (((t24 - t29) - t38) - t45),
        ((t5 + t22) + t28) - t39,
        ((t6 - t21) + t31) + t36,
        (((t7 + t11) - t14) + t20) + (((t25 - t30) + t37) + t44),
    );
}

// `gp` of a Motor and a Point.
fn pga3_motor_gp_point(a: pga3_Motor, b: pga3_Point) -> pga3_Odd {
    let t0 = a.scalar * b.e012;
    let t1 = a.scalar * b.e013;
    let t2 = a.scalar * b.e023;
    let t3 = a.scalar * b.e123;
    let t4 = a.e01 * b.e123;
    let t5 = a.e02 * b.e123;
    let t6 = a.e12 * b.e012;
    let t7 = a.e12 * b.e013;
    let t8 = a.e12 * b.e023;
    let t9 = a.e12 * b.e123;
    let t10 = a.e03 * b.e123;
    let t11 = a.e13 * b.e012;
    let t12 = a.e13 * b.e013;
    let t13 = a.e13 * b.e023;
    let t14 = a.e13 * b.e123;
    let t15 = a.e23 * b.e012;
    let t16 = a.e23 * b.e013;
    let t17 = a.e23 * b.e023;
    let t18 = a.e23 * b.e123;
    let t19 = a.e0123 * b.e123;
    return pga3_Odd(
        (((-t6) - t12) - t17) - t19,
        -t18,
        t14,
        -t9,
        ((t0 + t10) - t13) + t16,
        ((t1 - t5) + t8) - t15,
        ((t2 + t4) - t7) + t11,
        t3,
    );
}

// `gp` of a Motor and a Line.
fn pga3_motor_gp_line(a: pga3_Motor, b: pga3_Line) -> pga3_Motor {
    let t0 = a.scalar * b.e01;
    let t1 = a.scalar * b.e02;
    let t2 = a.scalar * b.e12;
    let t3 = a.scalar * b.e03;
    let t4 = a.scalar * b.e13;
    let t5 = a.scalar * b.e23;
    let t6 = a.e01 * b.e12;
    let t7 = a.e01 * b.e13;
    let t8 = a.e01 * b.e23;
    let t9 = a.e02 * b.e12;
    let t10 = a.e02 * b.e13;
    let t11 = a.e02 * b.e23;
    let t12 = a.e12 * b.e01;
    let t13 = a.e12 * b.e02;
    let t14 = a.e12 * b.e12;
    let t15 = a.e12 * b.e03;
    let t16 = a.e12 * b.e13;
    let t17 = a.e12 * b.e23;
    let t18 = a.e03 * b.e12;
    let t19 = a.e03 * b.e13;
    let t20 = a.e03 * b.e23;
    let t21 = a.e13 * b.e01;
    let t22 = a.e13 * b.e02;
    let t23 = a.e13 * b.e12;
    let t24 = a.e13 * b.e03;
    let t25 = a.e13 * b.e13;
    let t26 = a.e13 * b.e23;
    let t27 = a.e23 * b.e01;
    let t28 = a.e23 * b.e02;
    let t29 = a.e23 * b.e12;
    let t30 = a.e23 * b.e03;
    let t31 = a.e23 * b.e13;
    let t32 = a.e23 * b.e23;
    let t33 = a.e0123 * b.e12;
    let t34 = a.e0123 * b.e13;
    let t35 = a.e0123 * b.e23;
    return pga3_Motor(
        ((-t14) - t25) - t32,
        (((t0 - t9) + t13) - t19) + (t24 - t35),
        (((t1 + t6) - t12) - t20) + (t30 + t34),
        (t2 - t26) + t31,
        (((t3 + t7) + t11) - t21) - (t28 + t33),
        (t4 + t17) - t29,
        (t5 - t16) + t23,
        (((t8 - t10) + t15) + t18) - (t22 - t27),
    );
}

// `gp` of a Point and a Motor.
fn pga3_point_gp_motor(a: pga3_Point, b: pga3_Motor) -> pga3_Odd {
    let t0 = a.e012 * b.scalar;
    let t1 = a.e012 * b.e12;
    let t2 = a.e012 * b.e13;
    let t3 = a.e012 * b.e23;
    let t4 = a.e013 * b.scalar;
    let t5 = a.e013 * b.e12;
    let t6 = a.e013 * b.e13;
    let t7 = a.e013 * b.e23;
    let t8 = a.e023 * b.scalar;
    let t9 = a.e023 * b.e12;
    let t10 = a.e023 * b.e13;
    let t11 = a.e023 * b.e23;
    let t12 = a.e123 * b.scalar;
    let t13 = a.e123 * b.e01;
    let t14 = a.e123 * b.e02;
    let t15 = a.e123 * b.e12;
    let t16 = a.e123 * b.e03;
    let t17 = a.e123 * b.e13;
    let t18 = a.e123 * b.e23;
    let t19 = a.e123 * b.e0123;
    return pga3_Odd(
        ((t19 - t6) - t11) - t1,
        -t18,
        t17,
        -t15,
        ((t0 - t7) + t10) - t16,
        ((t3 + t4) - t9) + t14,
        ((t5 - t2) + t8) - t13,
        t12,
    );
}

// `gp` of a Point and a Point.
fn pga3_point_gp_point(a: pga3_Point, b: pga3_Point) -> pga3_Motor {
    let t0 = a.e012 * b.e123;
    let t1 = a.e013 * b.e123;
    let t2 = a.e023 * b.e123;
    let t3 = a.e123 * b.e012;
    let t4 = a.e123 * b.e013;
    let t5 = a.e123 * b.e023;
    let t6 = a.e123 * b.e123;
    return pga3_Motor(
        -t6,
        t5 - t2,
        t1 - t4,
        0.0f,
        t3 - t0,
        0.0f,
        0.0f,
        0.0f,
    );
}

// `gp` of a Point and a Line.
fn pga3_point_gp_line(a: pga3_Point, b: pga3_Line) -> pga3_Odd {
    let t0 = a.e012 * b.e12;
    let t1 = a.e012 * b.e13;
    let t2 = a.e012 * b.e23;
    let t3 = a.e013 * b.e12;
    let t4 = a.e013 * b.e13;
    let t5 = a.e013 * b.e23;
    let t6 = a.e023 * b.e12;
    let t7 = a.e023 * b.e13;
    let t8 = a.e023 * b.e23;
    let t9 = a.e123 * b.e01;
    let t10 = a.e123 * b.e02;
    let t11 = a.e123 * b.e12;
    let t12 = a.e123 * b.e03;
    let t13 = a.e123 * b.e13;
    let t14 = a.e123 * b.e23;
    return pga3_Odd(
        ((-t0) - t4) - t8,
        -t14,
        t13,
        -t11,
        (t7 - t5) - t12,
        (t2 - t6) + t10,
        (t3 - t1) - t9,
        0.0f,
    );
}

// `gp` of a Line and a Motor.
fn pga3_line_gp_motor(a: pga3_Line, b: pga3_Motor) -> pga3_Motor {
    let t0 = a.e01 * b.scalar;
    let t1 = a.e01 * b.e12;
    let t2 = a.e01 * b.e13;
    let t3 = a.e01 * b.e23;
    let t4 = a.e02 * b.scalar;
    let t5 = a.e02 * b.e12;
    let t6 = a.e02 * b.e13;
    let t7 = a.e02 * b.e23;
    let t8 = a.e12 * b.scalar;
    let t9 = a.e12 * b.e01;
    let t10 = a.e12 * b.e02;
    let t11 = a.e12 * b.e12;
    let t12 = a.e12 * b.e03;
    let t13 = a.e12 * b.e13;
    let t14 = a.e12 * b.e23;
    let t15 = a.e12 * b.e0123;
    let t16 = a.e03 * b.scalar;
    let t17 = a.e03 * b.e12;
    let t18 = a.e03 * b.e13;
    let t19 = a.e03 * b.e23;
    let t20 = a.e13 * b.scalar;
    let t21 = a.e13 * b.e01;
    let t22 = a.e13 * b.e02;
    let t23 = a.e13 * b.e12;
    let t24 = a.e13 * b.e03;
    let t25 = a.e13 * b.e13;
    let t26 = a.e13 * b.e23;
    let t27 = a.e13 * b.e0123;
    let t28 = a.e23 * b.scalar;
    let t29 = a.e23 * b.e01;
    let t30 = a.e23 * b.e02;
    let t31 = a.e23 * b.e12;
    let t32 = a.e23 * b.e03;
    let t33 = a.e23 * b.e13;
    let t34 = a.e23 * b.e23;
    let t35 = a.e23 * b.e0123;
    return pga3_Motor(
        ((-t11) - t25) - t34,
        (((t0 - t5) + t10) - t18) + (t24 - t35),
        (((t1 + t4) - t9) - t19) + (t27 + t32),
        (t8 - t26) + t33,
        (((t2 + t7) - t15) + t16) - (t21 + t30),
        (t14 + t20) - t31,
        (t23 - t13) + t28,
        (((t3 - t6) + t12) + t17) - (t22 - t29),
    );
}

// `gp` of a Line and a Point.
fn pga3_line_gp_point(a: pga3_Line, b: pga3_Point) -> pga3_Odd {
    let t0 = a.e01 * b.e123;
    let t1 = a.e02 * b.e123;
    let t2 = a.e12 * b.e012;
    let t3 = a.e12 * b.e013;
    let t4 = a.e12 * b.e023;
    let t5 = a.e12 * b.e123;
    let t6 = a.e03 * b.e123;
    let t7 = a.e13 * b.e012;
    let t8 = a.e13 * b.e013;
    let t9 = a.e13 * b.e023;
    let t10 = a.e13 * b.e123;
    let t11 = a.e23 * b.e012;
    let t12 = a.e23 * b.e013;
    let t13 = a.e23 * b.e023;
    let t14 = a.e23 * b.e123;
    return pga3_Odd(
        ((-t2) - t8) - t13,
        -t14,
        t10,
        -t5,
        (t6 - t9) + t12,
        (t4 - t1) - t11,
        (t0 - t3) + t7,
        0.0f,
    );
}

// `gp` of a Line and a Line.
fn pga3_line_gp_line(a: pga3_Line, b: pga3_Line) -> pga3_Motor {
    let t0 = a.e01 * b.e12;
    let t1 = a.e01 * b.e13;
    let t2 = a.e01 * b.e23;
    let t3 = a.e02 * b.e12;
    let t4 = a.e02 * b.e13;
    let t5 = a.e02 * b.e23;
    let t6 = a.e12 * b.e01;
    let t7 = a.e12 * b.e02;
    let t8 = a.e12 * b.e12;
    let t9 = a.e12 * b.e03;
    let t10 = a.e12 * b.e13;
    let t11 = a.e12 * b.e23;
    let t12 = a.e03 * b.e12;
    let t13 = a.e03 * b.e13;
    let t14 = a.e03 * b.e23;
    let t15 = a.e13 * b.e01;
    let t16 = a.e13 * b.e02;
    let t17 = a.e13 * b.e12;
    let t18 = a.e13 * b.e03;
    let t19 = a.e13 * b.e13;
    let t20 = a.e13 * b.e23;
    let t21 = a.e23 * b.e01;
    let t22 = a.e23 * b.e02;
    let t23 = a.e23 * b.e12;
    let t24 = a.e23 * b.e03;
    let t25 = a.e23 * b.e13;
    let t26 = a.e23 * b.e23;
    return pga3_Motor(
        ((-t8) - t19) - t26,
        ((t7 - t3) - t13) + t18,
        ((t0 - t6) - t14) + t24,
        t25 - t20,
        ((t1 + t5) - t15) - t22,
        t11 - t23,
        t17 - t10,
        (((t2 - t4) + t9) + t12) - (t16 - t21),
    );
}

// The reverse of a Motor.
fn pga3_motor_reverse(x: pga3_Motor) -> pga3_Motor {
    return pga3_Motor(
        x.scalar,
        -x.e01,
        -x.e02,
        -x.e12,
        -x.e03,
        -x.e13,
        -x.e23,
        x.e0123,
    );
}

// The squared norm <x rev(x)>_0 of a Motor (may be negative or zero).
fn pga3_motor_norm_squared(x: pga3_Motor) -> f32 {
    let t0 = x.scalar * x.scalar;
    let t1 = x.e12 * x.e12;
    let t2 = x.e13 * x.e13;
    let t3 = x.e23 * x.e23;
    return ((t0 + t1) + t2) + t3;
}

// The reverse of a Point.
fn pga3_point_reverse(x: pga3_Point) -> pga3_Point {
    return pga3_Point(
        -x.e012,
        -x.e013,
        -x.e023,
        -x.e123,
    );
}

// The squared norm <x rev(x)>_0 of a Point (may be negative or zero).
fn pga3_point_norm_squared(x: pga3_Point) -> f32 {
    let t0 = x.e123 * x.e123;
    return t0;
}

// The reverse of a Line.
fn pga3_line_reverse(x: pga3_Line) -> pga3_Line {
    return pga3_Line(
        -x.e01,
        -x.e02,
        -x.e12,
        -x.e03,
        -x.e13,
        -x.e23,
    );
}

// The squared norm <x rev(x)>_0 of a Line (may be negative or zero).
fn pga3_line_norm_squared(x: pga3_Line) -> f32 {
    let t0 = x.e12 * x.e12;
    let t1 = x.e13 * x.e13;
    let t2 = x.e23 * x.e23;
    return (t0 + t1) + t2;
}

// S x rev(S) for a Motor S and a Motor x, in one fused kernel.
fn pga3_motor_apply_motor(s: pga3_Motor, x: pga3_Motor) -> pga3_Motor {
    let t0 = ((s.scalar * x.scalar) - (s.e12 * x.e12)) - ((s.e13 * x.e13) + (s.e23 * x.e23));
    let t1 = (((s.scalar * x.e01) + (s.e01 * x.scalar)) - ((s.e02 * x.e12) - (s.e12 * x.e02))) - (((s.e03 * x.e13) - (s.e13 * x.e03)) + ((s.e23 * x.e0123) + (s.e0123 * x.e23)));
    let t2 = (((s.scalar * x.e02) + (s.e01 * x.e12)) + ((s.e02 * x.scalar) - (s.e12 * x.e01))) - (((s.e03 * x.e23) - (s.e13 * x.e0123)) - ((s.e23 * x.e03) + (s.e0123 * x.e13)));
    let t3 = ((s.scalar * x.e12) + (s.e12 * x.scalar)) - ((s.e13 * x.e23) - (s.e23 * x.e13));
    let t4 = (((s.scalar * x.e03) + (s.e01 * x.e13)) + ((s.e02 * x.e23) - (s.e12 * x.e0123))) + (((s.e03 * x.scalar) - (s.e13 * x.e01)) - ((s.e23 * x.e02) + (s.e0123 * x.e12)));
    let t5 = ((s.scalar * x.e13) + (s.e12 * x.e23)) + ((s.e13 * x.scalar) - (s.e23 * x.e12));
    let t6 = ((s.scalar * x.e23) - (s.e12 * x.e13)) + ((s.e13 * x.e12) + (s.e23 * x.scalar));
    let t7 = (((s.scalar * x.e0123) + (s.e01 * x.e23)) - ((s.e02 * x.e13) - (s.e12 * x.e03))) + (((s.e03 * x.e12) - (s.e13 * x.e02)) + ((s.e23 * x.e01) + (s.e0123 * x.scalar)));
    return pga3_Motor(
        ((t0 * s.scalar) + (t3 * s.e12)) + ((t5 * s.e13) + (t6 * s.e23)),
        (((t1 * s.scalar) - (t0 * s.e01)) - ((t3 * s.e02) - (t2 * s.e12))) - (((t5 * s.e03) - (t4 * s.e13)) - ((t7 * s.e23) - (t6 * s.e0123))),
        (((t2 * s.scalar) + (t3 * s.e01)) - ((t0 * s.e02) + (t1 * s.e12))) - (((t6 * s.e03) + (t7 * s.e13)) - ((t4 * s.e23) + (t5 * s.e0123))),
        ((t3 * s.scalar) - (t0 * s.e12)) - ((t6 * s.e13) - (t5 * s.e23)),
        (((t4 * s.scalar) + (t5 * s.e01)) + ((t6 * s.e02) + (t7 * s.e12))) - (((t0 * s.e03) + (t1 * s.e13)) + ((t2 * s.e23) + (t3 * s.e0123))),
        ((t5 * s.scalar) + (t6 * s.e12)) - ((t0 * s.e13) + (t3 * s.e23)),
        ((t6 * s.scalar) - (t5 * s.e12)) + ((t3 * s.e13) - (t0 * s.e23)),
        (((t7 * s.scalar) - (t6 * s.e01)) + ((t5 * s.e02) - (t4 * s.e12))) - (((t3 * s.e03) - (t2 * s.e13)) + ((t1 * s.e23) - (t0 * s.e0123))),
    );
}

// S x rev(S) for a Motor S and a Point x, in one fused kernel.
fn pga3_motor_apply_point(s: pga3_Motor, x: pga3_Point) -> pga3_Point {
    let t0 = (-s.e0123) * x.e123;
    let t1 = (s.e03 * x.e123) - ((s.e13 * x.e023) + ((-s.e23) * x.e013));
    let t2 = -((s.e02 * x.e123) - ((s.e12 * x.e023) + ((-s.e23) * x.e012)));
    let t3 = (s.e01 * x.e123) - ((s.e12 * x.e013) - (s.e13 * x.e012));
    let t4 = ((s.scalar * s.scalar) + (s.e23 * s.e23)) + ((s.e12 * s.e12) + (s.e13 * s.e13));
    let t5 = (((t1 * s.scalar) - (t0 * s.e12)) - (t3 * s.e13)) - (t2 * (-s.e23));
    let t6 = (((t2 * s.scalar) + (t3 * s.e12)) + (t1 * (-s.e23))) - (t0 * s.e13);
    let t7 = (((t3 * s.scalar) + (t1 * s.e13)) + (t0 * (-s.e23))) - (t2 * s.e12);
    return pga3_Point(
        (t4 * x.e012) + (t5 + t5),
        (t4 * x.e013) + (t6 + t6),
        (t4 * x.e023) + (t7 + t7),
        t4 * x.e123,
    );
}

// S x rev(S) for a Motor S and a Line x, in one fused kernel.
fn pga3_motor_apply_line(s: pga3_Motor, x: pga3_Line) -> pga3_Line {
    let t0 = -((s.e12 * x.e12) + ((s.e13 * x.e13) + (s.e23 * x.e23)));
    let t1 = ((s.scalar * x.e01) - ((s.e02 * x.e12) - (s.e12 * x.e02))) - ((s.e03 * x.e13) - ((s.e13 * x.e03) - (s.e0123 * x.e23)));
    let t2 = ((s.scalar * x.e02) + ((s.e01 * x.e12) - (s.e12 * x.e01))) - ((s.e03 * x.e23) - ((s.e23 * x.e03) + (s.e0123 * x.e13)));
    let t3 = (s.scalar * x.e12) - ((s.e13 * x.e23) - (s.e23 * x.e13));
    let t4 = ((s.scalar * x.e03) + ((s.e01 * x.e13) + (s.e02 * x.e23))) - ((s.e13 * x.e01) + ((s.e23 * x.e02) + (s.e0123 * x.e12)));
    let t5 = (s.scalar * x.e13) + ((s.e12 * x.e23) - (s.e23 * x.e12));
    let t6 = (s.scalar * x.e23) - ((s.e12 * x.e13) - (s.e13 * x.e12));
    let t7 = ((s.e01 * x.e23) - ((s.e02 * x.e13) - (s.e12 * x.e03))) + ((s.e03 * x.e12) - ((s.e13 * x.e02) - (s.e23 * x.e01)));
    return pga3_Line(
        (((t1 * s.scalar) - (t0 * s.e01)) - ((t3 * s.e02) - (t2 * s.e12))) - (((t5 * s.e03) - (t4 * s.e13)) - ((t7 * s.e23) - (t6 * s.e0123))),
        (((t2 * s.scalar) + (t3 * s.e01)) - ((t0 * s.e02) + (t1 * s.e12))) - (((t6 * s.e03) + (t7 * s.e13)) - ((t4 * s.e23) + (t5 * s.e0123))),
        ((t3 * s.scalar) - (t0 * s.e12)) - ((t6 * s.e13) - (t5 * s.e23)),
        (((t4 * s.scalar) + (t5 * s.e01)) + ((t6 * s.e02) + (t7 * s.e12))) - (((t0 * s.e03) + (t1 * s.e13)) + ((t2 * s.e23) + (t3 * s.e0123))),
        ((t5 * s.scalar) + (t6 * s.e12)) - ((t0 * s.e13) + (t3 * s.e23)),
        ((t6 * s.scalar) - (t5 * s.e12)) + ((t3 * s.e13) - (t0 * s.e23)),
    );
}

// S x rev(S) for a Point S and a Motor x, in one fused kernel.
fn pga3_point_apply_motor(s: pga3_Point, x: pga3_Motor) -> pga3_Motor {
    let t0 = s.e123 * x.e0123;
    let t1 = -((s.e013 * x.e23) - ((s.e023 * x.e13) - (s.e123 * x.e03)));
    let t2 = (s.e012 * x.e23) - ((s.e023 * x.e12) - (s.e123 * x.e02));
    let t3 = -((s.e012 * x.e13) - ((s.e013 * x.e12) - (s.e123 * x.e01)));
    let t4 = s.e123 * s.e123;
    let t5 = t3 * s.e123;
    let t6 = -(t2 * s.e123);
    let t7 = t1 * s.e123;
    let t8 = -(t0 * s.e123);
    return pga3_Motor(
        t4 * x.scalar,
        (t4 * x.e01) + (t5 + t5),
        (t4 * x.e02) + (t6 + t6),
        t4 * x.e12,
        (t4 * x.e03) + (t7 + t7),
        t4 * x.e13,
        t4 * x.e23,
        (t4 * x.e0123) + (t8 + t8),
    );
}

// S x rev(S) for a Point S and a Point x, in one fused kernel.
fn pga3_point_apply_point(s: pga3_Point, x: pga3_Point) -> pga3_Point {
    let t0 = -(s.e123 * x.e123);
    let t1 = -((s.e023 * x.e123) - (s.e123 * x.e023));
    let t2 = (s.e013 * x.e123) - (s.e123 * x.e013);
    let t3 = -((s.e012 * x.e123) - (s.e123 * x.e012));
    return pga3_Point(
        -((t0 * s.e012) + (t3 * s.e123)),
        (t2 * s.e123) - (t0 * s.e013),
        -((t0 * s.e023) + (t1 * s.e123)),
        -(t0 * s.e123),
    );
}

// S x rev(S) for a Point S and a Line x, in one fused kernel.
fn pga3_point_apply_line(s: pga3_Point, x: pga3_Line) -> pga3_Line {
    let t0 = -(s.e123 * x.e23);
    let t1 = s.e123 * x.e13;
    let t2 = -((s.e013 * x.e23) - ((s.e023 * x.e13) - (s.e123 * x.e03)));
    let t3 = -(s.e123 * x.e12);
    let t4 = (s.e012 * x.e23) - ((s.e023 * x.e12) - (s.e123 * x.e02));
    let t5 = -((s.e012 * x.e13) - ((s.e013 * x.e12) - (s.e123 * x.e01)));
    return pga3_Line(
        (t5 * s.e123) - ((t1 * s.e012) + (t3 * s.e013)),
        (t0 * s.e012) - ((t3 * s.e023) + (t4 * s.e123)),
        -(t3 * s.e123),
        (t0 * s.e013) + ((t1 * s.e023) + (t2 * s.e123)),
        t1 * s.e123,
        -(t0 * s.e123),
    );
}

// S x rev(S) for a Line S and a Motor x, in one fused kernel.
fn pga3_line_apply_motor(s: pga3_Line, x: pga3_Motor) -> pga3_Motor {
    let t0 = -((s.e12 * x.e12) + ((s.e13 * x.e13) + (s.e23 * x.e23)));
    let t1 = ((s.e01 * x.scalar) - ((s.e02 * x.e12) - (s.e12 * x.e02))) - ((s.e03 * x.e13) - ((s.e13 * x.e03) - (s.e23 * x.e0123)));
    let t2 = ((s.e01 * x.e12) + ((s.e02 * x.scalar) - (s.e12 * x.e01))) - ((s.e03 * x.e23) - ((s.e13 * x.e0123) + (s.e23 * x.e03)));
    let t3 = (s.e12 * x.scalar) - ((s.e13 * x.e23) - (s.e23 * x.e13));
    let t4 = ((s.e01 * x.e13) + ((s.e02 * x.e23) - (s.e12 * x.e0123))) + ((s.e03 * x.scalar) - ((s.e13 * x.e01) + (s.e23 * x.e02)));
    let t5 = (s.e12 * x.e23) + ((s.e13 * x.scalar) - (s.e23 * x.e12));
    let t6 = -((s.e12 * x.e13) - ((s.e13 * x.e12) + (s.e23 * x.scalar)));
    let t7 = ((s.e01 * x.e23) - ((s.e02 * x.e13) - (s.e12 * x.e03))) + ((s.e03 * x.e12) - ((s.e13 * x.e02) - (s.e23 * x.e01)));
    return pga3_Motor(
        (t3 * s.e12) + ((t5 * s.e13) + (t6 * s.e23)),
        ((t2 * s.e12) - ((t0 * s.e01) + (t3 * s.e02))) - ((t5 * s.e03) - ((t4 * s.e13) + (t7 * s.e23))),
        ((t3 * s.e01) - ((t0 * s.e02) + (t1 * s.e12))) - ((t6 * s.e03) + ((t7 * s.e13) - (t4 * s.e23))),
        (t5 * s.e23) - ((t0 * s.e12) + (t6 * s.e13)),
        ((t5 * s.e01) + ((t6 * s.e02) + (t7 * s.e12))) - ((t0 * s.e03) + ((t1 * s.e13) + (t2 * s.e23))),
        (t6 * s.e12) - ((t0 * s.e13) + (t3 * s.e23)),
        (t3 * s.e13) - ((t5 * s.e12) + (t0 * s.e23)),
        ((t5 * s.e02) - ((t6 * s.e01) + (t4 * s.e12))) - ((t3 * s.e03) - ((t2 * s.e13) - (t1 * s.e23))),
    );
}

// S x rev(S) for a Line S and a Point x, in one fused kernel.
fn pga3_line_apply_point(s: pga3_Line, x: pga3_Point) -> pga3_Point {
    let t0 = (s.e03 * x.e123) - ((s.e13 * x.e023) - (s.e23 * x.e013));
    let t1 = -((s.e02 * x.e123) - ((s.e12 * x.e023) - (s.e23 * x.e012)));
    let t2 = (s.e01 * x.e123) - ((s.e12 * x.e013) - (s.e13 * x.e012));
    let t3 = (s.e12 * s.e12) + ((s.e13 * s.e13) + (s.e23 * s.e23));
    let t4 = (t1 * s.e23) - (t2 * s.e13);
    let t5 = (t2 * s.e12) - (t0 * s.e23);
    let t6 = (t0 * s.e13) - (t1 * s.e12);
    return pga3_Point(
        (t3 * x.e012) + (t4 + t4),
        (t3 * x.e013) + (t5 + t5),
        (t3 * x.e023) + (t6 + t6),
        t3 * x.e123,
    );
}

// S x rev(S) for a Line S and a Line x, in one fused kernel.
fn pga3_line_apply_line(s: pga3_Line, x: pga3_Line) -> pga3_Line {
    let t0 = -((s.e12 * x.e12) + ((s.e13 * x.e13) + (s.e23 * x.e23)));
    let t1 = -(((s.e02 * x.e12) - (s.e12 * x.e02)) + ((s.e03 * x.e13) - (s.e13 * x.e03)));
    let t2 = ((s.e01 * x.e12) - (s.e12 * x.e01)) - ((s.e03 * x.e23) - (s.e23 * x.e03));
    let t3 = -((s.e13 * x.e23) - (s.e23 * x.e13));
    let t4 = ((s.e01 * x.e13) + (s.e02 * x.e23)) - ((s.e13 * x.e01) + (s.e23 * x.e02));
    let t5 = (s.e12 * x.e23) - (s.e23 * x.e12);
    let t6 = -((s.e12 * x.e13) - (s.e13 * x.e12));
    let t7 = ((s.e01 * x.e23) - ((s.e02 * x.e13) - (s.e12 * x.e03))) + ((s.e03 * x.e12) - ((s.e13 * x.e02) - (s.e23 * x.e01)));
    return pga3_Line(
        ((t2 * s.e12) - ((t0 * s.e01) + (t3 * s.e02))) - ((t5 * s.e03) - ((t4 * s.e13) + (t7 * s.e23))),
        ((t3 * s.e01) - ((t0 * s.e02) + (t1 * s.e12))) - ((t6 * s.e03) + ((t7 * s.e13) - (t4 * s.e23))),
        (t5 * s.e23) - ((t0 * s.e12) + (t6 * s.e13)),
        ((t5 * s.e01) + ((t6 * s.e02) + (t7 * s.e12))) - ((t0 * s.e03) + ((t1 * s.e13) + (t2 * s.e23))),
        (t6 * s.e12) - ((t0 * s.e13) + (t3 * s.e23)),
        (t3 * s.e13) - ((t5 * s.e12) + (t0 * s.e23)),
    );
}

// S x rev(S) for a unit Motor S (S rev(S) = 1) and a Motor x; not the action otherwise.
fn pga3_motor_apply_unit_motor(s: pga3_Motor, x: pga3_Motor) -> pga3_Motor {
    let t0 = -(((s.e02 * x.e12) - (s.e12 * x.e02)) + ((s.e03 * x.e13) - (s.e13 * x.e03)));
    let t1 = ((s.e01 * x.e12) - (s.e12 * x.e01)) - ((s.e03 * x.e23) - (s.e23 * x.e03));
    let t2 = -((s.e13 * x.e23) - (s.e23 * x.e13));
    let t3 = ((s.e01 * x.e13) + (s.e02 * x.e23)) - ((s.e13 * x.e01) + (s.e23 * x.e02));
    let t4 = (s.e12 * x.e23) - (s.e23 * x.e12);
    let t5 = -((s.e12 * x.e13) - (s.e13 * x.e12));
    let t6 = ((t0 * s.scalar) + ((t1 * s.e12) - (t2 * s.e02))) + ((t3 * s.e13) - ((t4 * s.e03) + (t5 * s.e0123)));
    let t7 = -(((t0 * s.e12) - ((t1 * s.scalar) + (t2 * s.e01))) - ((t3 * s.e23) + ((t4 * s.e0123) - (t5 * s.e03))));
    let t8 = (t2 * s.scalar) + ((t4 * s.e23) - (t5 * s.e13));
    let t9 = -(((t0 * s.e13) + ((t1 * s.e23) + (t2 * s.e0123))) - ((t3 * s.scalar) + ((t4 * s.e01) + (t5 * s.e02))));
    let t10 = -((t2 * s.e23) - ((t4 * s.scalar) + (t5 * s.e12)));
    let t11 = (t2 * s.e13) - ((t4 * s.e12) - (t5 * s.scalar));
    return pga3_Motor(
        x.scalar,
        (x.e01 + t6) + t6,
        (x.e02 + t7) + t7,
        (x.e12 + t8) + t8,
        (x.e03 + t9) + t9,
        (x.e13 + t10) + t10,
        (x.e23 + t11) + t11,
        x.e0123,
    );
}

// S x rev(S) for a unit Motor S (S rev(S) = 1) and a Point x; not the action otherwise.
fn pga3_motor_apply_unit_point(s: pga3_Motor, x: pga3_Point) -> pga3_Point {
    let t0 = -(s.e0123 * x.e123);
    let t1 = (s.e03 * x.e123) - ((s.e13 * x.e023) - (s.e23 * x.e013));
    let t2 = -((s.e02 * x.e123) - ((s.e12 * x.e023) - (s.e23 * x.e012)));
    let t3 = (s.e01 * x.e123) - ((s.e12 * x.e013) - (s.e13 * x.e012));
    let t4 = -(((t0 * s.e12) - (t1 * s.scalar)) - ((t2 * s.e23) - (t3 * s.e13)));
    let t5 = -(((t0 * s.e13) + (t1 * s.e23)) - ((t2 * s.scalar) + (t3 * s.e12)));
    let t6 = -(((t0 * s.e23) - (t1 * s.e13)) + ((t2 * s.e12) - (t3 * s.scalar)));
    return pga3_Point(
        (x.e012 + t4) + t4,
        (x.e013 + t5) + t5,
        (x.e023 + t6) + t6,
        x.e123,
    );
}

// S x rev(S) for a unit Motor S (S rev(S) = 1) and a Line x; not the action otherwise.
fn pga3_motor_apply_unit_line(s: pga3_Motor, x: pga3_Line) -> pga3_Line {
    let t0 = -(((s.e02 * x.e12) - (s.e12 * x.e02)) + ((s.e03 * x.e13) - (s.e13 * x.e03)));
    let t1 = ((s.e01 * x.e12) - (s.e12 * x.e01)) - ((s.e03 * x.e23) - (s.e23 * x.e03));
    let t2 = -((s.e13 * x.e23) - (s.e23 * x.e13));
    let t3 = ((s.e01 * x.e13) + (s.e02 * x.e23)) - ((s.e13 * x.e01) + (s.e23 * x.e02));
    let t4 = (s.e12 * x.e23) - (s.e23 * x.e12);
    let t5 = -((s.e12 * x.e13) - (s.e13 * x.e12));
    let t6 = ((t0 * s.scalar) + ((t1 * s.e12) - (t2 * s.e02))) + ((t3 * s.e13) - ((t4 * s.e03) + (t5 * s.e0123)));
    let t7 = -(((t0 * s.e12) - ((t1 * s.scalar) + (t2 * s.e01))) - ((t3 * s.e23) + ((t4 * s.e0123) - (t5 * s.e03))));
    let t8 = (t2 * s.scalar) + ((t4 * s.e23) - (t5 * s.e13));
    let t9 = -(((t0 * s.e13) + ((t1 * s.e23) + (t2 * s.e0123))) - ((t3 * s.scalar) + ((t4 * s.e01) + (t5 * s.e02))));
    let t10 = -((t2 * s.e23) - ((t4 * s.scalar) + (t5 * s.e12)));
    let t11 = (t2 * s.e13) - ((t4 * s.e12) - (t5 * s.scalar));
    return pga3_Line(
        (x.e01 + t6) + t6,
        (x.e02 + t7) + t7,
        (x.e12 + t8) + t8,
        (x.e03 + t9) + t9,
        (x.e13 + t10) + t10,
        (x.e23 + t11) + t11,
    );
}

// S x rev(S) for a unit Point S (S rev(S) = 1) and a Motor x; not the action otherwise.
fn pga3_point_apply_unit_motor(s: pga3_Point, x: pga3_Motor) -> pga3_Motor {
    let t0 = s.e123 * x.e0123;
    let t1 = -((s.e013 * x.e23) - ((s.e023 * x.e13) - (s.e123 * x.e03)));
    let t2 = (s.e012 * x.e23) - ((s.e023 * x.e12) - (s.e123 * x.e02));
    let t3 = -((s.e012 * x.e13) - ((s.e013 * x.e12) - (s.e123 * x.e01)));
    let t4 = t3 * s.e123;
    let t5 = -(t2 * s.e123);
    let t6 = t1 * s.e123;
    let t7 = -(t0 * s.e123);
    return pga3_Motor(
        x.scalar,
        (x.e01 + t4) + t4,
        (x.e02 + t5) + t5,
        x.e12,
        (x.e03 + t6) + t6,
        x.e13,
        x.e23,
        (x.e0123 + t7) + t7,
    );
}

// S x rev(S) for a unit Point S (S rev(S) = 1) and a Point x; not the action otherwise.
fn pga3_point_apply_unit_point(s: pga3_Point, x: pga3_Point) -> pga3_Point {
    let t0 = -((s.e023 * x.e123) - (s.e123 * x.e023));
    let t1 = (s.e013 * x.e123) - (s.e123 * x.e013);
    let t2 = -((s.e012 * x.e123) - (s.e123 * x.e012));
    let t3 = -(t2 * s.e123);
    let t4 = t1 * s.e123;
    let t5 = -(t0 * s.e123);
    return pga3_Point(
        (x.e012 + t3) + t3,
        (x.e013 + t4) + t4,
        (x.e023 + t5) + t5,
        x.e123,
    );
}

// S x rev(S) for a unit Point S (S rev(S) = 1) and a Line x; not the action otherwise.
fn pga3_point_apply_unit_line(s: pga3_Point, x: pga3_Line) -> pga3_Line {
    let t0 = -((s.e013 * x.e23) - ((s.e023 * x.e13) - (s.e123 * x.e03)));
    let t1 = (s.e012 * x.e23) - ((s.e023 * x.e12) - (s.e123 * x.e02));
    let t2 = -((s.e012 * x.e13) - ((s.e013 * x.e12) - (s.e123 * x.e01)));
    let t3 = t2 * s.e123;
    let t4 = -(t1 * s.e123);
    let t5 = t0 * s.e123;
    return pga3_Line(
        (x.e01 + t3) + t3,
        (x.e02 + t4) + t4,
        x.e12,
        (x.e03 + t5) + t5,
        x.e13,
        x.e23,
    );
}

// S x rev(S) for a unit Line S (S rev(S) = 1) and a Motor x; not the action otherwise.
fn pga3_line_apply_unit_motor(s: pga3_Line, x: pga3_Motor) -> pga3_Motor {
    let t0 = -(((s.e02 * x.e12) - (s.e12 * x.e02)) + ((s.e03 * x.e13) - (s.e13 * x.e03)));
    let t1 = ((s.e01 * x.e12) - (s.e12 * x.e01)) - ((s.e03 * x.e23) - (s.e23 * x.e03));
    let t2 = -((s.e13 * x.e23) - (s.e23 * x.e13));
    let t3 = ((s.e01 * x.e13) + (s.e02 * x.e23)) - ((s.e13 * x.e01) + (s.e23 * x.e02));
    let t4 = (s.e12 * x.e23) - (s.e23 * x.e12);
    let t5 = -((s.e12 * x.e13) - (s.e13 * x.e12));
    let t6 = ((t1 * s.e12) - (t2 * s.e02)) + ((t3 * s.e13) - (t4 * s.e03));
    let t7 = -(((t0 * s.e12) - (t2 * s.e01)) - ((t3 * s.e23) - (t5 * s.e03)));
    let t8 = (t4 * s.e23) - (t5 * s.e13);
    let t9 = -(((t0 * s.e13) + (t1 * s.e23)) - ((t4 * s.e01) + (t5 * s.e02)));
    let t10 = -((t2 * s.e23) - (t5 * s.e12));
    let t11 = (t2 * s.e13) - (t4 * s.e12);
    return pga3_Motor(
        x.scalar,
        (x.e01 + t6) + t6,
        (x.e02 + t7) + t7,
        (x.e12 + t8) + t8,
        (x.e03 + t9) + t9,
        (x.e13 + t10) + t10,
        (x.e23 + t11) + t11,
        x.e0123,
    );
}

// S x rev(S) for a unit Line S (S rev(S) = 1) and a Point x; not the action otherwise.
fn pga3_line_apply_unit_point(s: pga3_Line, x: pga3_Point) -> pga3_Point {
    let t0 = (s.e03 * x.e123) - ((s.e13 * x.e023) - (s.e23 * x.e013));
    let t1 = -((s.e02 * x.e123) - ((s.e12 * x.e023) - (s.e23 * x.e012)));
    let t2 = (s.e01 * x.e123) - ((s.e12 * x.e013) - (s.e13 * x.e012));
    let t3 = (t1 * s.e23) - (t2 * s.e13);
    let t4 = -((t0 * s.e23) - (t2 * s.e12));
    let t5 = (t0 * s.e13) - (t1 * s.e12);
    return pga3_Point(
        (x.e012 + t3) + t3,
        (x.e013 + t4) + t4,
        (x.e023 + t5) + t5,
        x.e123,
    );
}

// S x rev(S) for a unit Line S (S rev(S) = 1) and a Line x; not the action otherwise.
fn pga3_line_apply_unit_line(s: pga3_Line, x: pga3_Line) -> pga3_Line {
    let t0 = -(((s.e02 * x.e12) - (s.e12 * x.e02)) + ((s.e03 * x.e13) - (s.e13 * x.e03)));
    let t1 = ((s.e01 * x.e12) - (s.e12 * x.e01)) - ((s.e03 * x.e23) - (s.e23 * x.e03));
    let t2 = -((s.e13 * x.e23) - (s.e23 * x.e13));
    let t3 = ((s.e01 * x.e13) + (s.e02 * x.e23)) - ((s.e13 * x.e01) + (s.e23 * x.e02));
    let t4 = (s.e12 * x.e23) - (s.e23 * x.e12);
    let t5 = -((s.e12 * x.e13) - (s.e13 * x.e12));
    let t6 = ((t1 * s.e12) - (t2 * s.e02)) + ((t3 * s.e13) - (t4 * s.e03));
    let t7 = -(((t0 * s.e12) - (t2 * s.e01)) - ((t3 * s.e23) - (t5 * s.e03)));
    let t8 = (t4 * s.e23) - (t5 * s.e13);
    let t9 = -(((t0 * s.e13) + (t1 * s.e23)) - ((t4 * s.e01) + (t5 * s.e02)));
    let t10 = -((t2 * s.e23) - (t5 * s.e12));
    let t11 = (t2 * s.e13) - (t4 * s.e12);
    return pga3_Line(
        (x.e01 + t6) + t6,
        (x.e02 + t7) + t7,
        (x.e12 + t8) + t8,
        (x.e03 + t9) + t9,
        (x.e13 + t10) + t10,
        (x.e23 + t11) + t11,
    );
}

// exp of a Line: a unit Motor (closed form; non-finite input gives non-finite output).
fn pga3_line_exp(x: pga3_Line) -> pga3_Motor {
    let t0 = ((x.e12 * x.e12) + (x.e13 * x.e13)) + (x.e23 * x.e23);
    let t1 = pga3_exp_factors(t0);
    let t2 = ((x.e01 * x.e23) - (x.e02 * x.e13)) + (x.e12 * x.e03);
    let t3 = t2 * t1.y;
    return pga3_Motor(
        t1.z,
        (t1.x * x.e01) + (t3 * x.e23),
        (t1.x * x.e02) - (t3 * x.e13),
        t1.x * x.e12,
        (t1.x * x.e03) + (t3 * x.e12),
        t1.x * x.e13,
        t1.x * x.e23,
        t2 * t1.x,
    );
}

// log of a unit Motor (m rev(m) = 1): the Line B with exp(B) = m, angle in [0, pi); a full turn gives non-finite output.
fn pga3_motor_log_unit(x: pga3_Motor) -> pga3_Line {
    let t0 = sqrt(((x.e12 * x.e12) + (x.e13 * x.e13)) + (x.e23 * x.e23));
    let t1 = pga3_log_factors(t0, x.scalar);
    let t2 = x.e0123 * t1.y;
    return pga3_Line(
        (t1.x * x.e01) - (t2 * x.e23),
        (t1.x * x.e02) + (t2 * x.e13),
        t1.x * x.e12,
        (t1.x * x.e03) - (t2 * x.e12),
        t1.x * x.e13,
        t1.x * x.e23,
    );
}

// m / sqrt(m rev(m)) for a Motor: a unit Motor; a non-positive norm gives non-finite output.
fn pga3_motor_normalize(x: pga3_Motor) -> pga3_Motor {
    let t0 = (x.scalar * x.scalar) - (((-(x.e12 * x.e12)) - (x.e13 * x.e13)) - (x.e23 * x.e23));
    let t1 = 1.0f / t0;
    let t2 = (x.scalar * x.e0123) - (((x.e01 * x.e23) - (x.e02 * x.e13)) + (x.e12 * x.e03));
    let t3 = sqrt(t1);
    let t4 = (-(t2 * t3)) * t1;
    return pga3_Motor(
        x.scalar * t3,
        (x.e01 * t3) + (-(t4 * x.e23)),
        (x.e02 * t3) + (t4 * x.e13),
        x.e12 * t3,
        (x.e03 * t3) + (-(t4 * x.e12)),
        x.e13 * t3,
        x.e23 * t3,
        (x.e0123 * t3) + (x.scalar * t4),
    );
}

