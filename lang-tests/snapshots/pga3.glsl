// pga3: Motor=even;Point=grade3;Line=grade2; ops gp,apply,apply_unit,reverse,norm_squared,exp,log_unit,normalize
// Motor: the coefficients of scalar, e01, e02, e12, e03, e13, e23, e0123.
struct pga3_Motor {
    float scalar;
    float e01;
    float e02;
    float e12;
    float e03;
    float e13;
    float e23;
    float e0123;
};

// Point: the coefficients of e012, e013, e023, e123.
struct pga3_Point {
    float e012;
    float e013;
    float e023;
    float e123;
};

// Line: the coefficients of e01, e02, e12, e03, e13, e23.
struct pga3_Line {
    float e01;
    float e02;
    float e12;
    float e03;
    float e13;
    float e23;
};

// The odd part of the algebra, declared automatically: some product of the declared types lands here.
// Odd: the coefficients of e0, e1, e2, e3, e012, e013, e023, e123.
struct pga3_Odd {
    float e0;
    float e1;
    float e2;
    float e3;
    float e012;
    float e013;
    float e023;
    float e123;
};

// (sinc t, (cos t - sinc t) / t^2, cos t) from t^2 >= 0 (series below t = 1e-3).
vec3 pga3_exp_factors(float theta2) {
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
vec3 pga3_log_factors(float si, float co) {
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
pga3_Motor pga3_motor_gp_motor(pga3_Motor a, pga3_Motor b) {
    float t0 = a.scalar * b.scalar;
    float t1 = a.scalar * b.e01;
    float t2 = a.scalar * b.e02;
    float t3 = a.scalar * b.e12;
    float t4 = a.scalar * b.e03;
    float t5 = a.scalar * b.e13;
    float t6 = a.scalar * b.e23;
    float t7 = a.scalar * b.e0123;
    float t8 = a.e01 * b.scalar;
    float t9 = a.e01 * b.e12;
    float t10 = a.e01 * b.e13;
    float t11 = a.e01 * b.e23;
    float t12 = a.e02 * b.scalar;
    float t13 = a.e02 * b.e12;
    float t14 = a.e02 * b.e13;
    float t15 = a.e02 * b.e23;
    float t16 = a.e12 * b.scalar;
    float t17 = a.e12 * b.e01;
    float t18 = a.e12 * b.e02;
    float t19 = a.e12 * b.e12;
    float t20 = a.e12 * b.e03;
    float t21 = a.e12 * b.e13;
    float t22 = a.e12 * b.e23;
    float t23 = a.e12 * b.e0123;
    float t24 = a.e03 * b.scalar;
    float t25 = a.e03 * b.e12;
    float t26 = a.e03 * b.e13;
    float t27 = a.e03 * b.e23;
    float t28 = a.e13 * b.scalar;
    float t29 = a.e13 * b.e01;
    float t30 = a.e13 * b.e02;
    float t31 = a.e13 * b.e12;
    float t32 = a.e13 * b.e03;
    float t33 = a.e13 * b.e13;
    float t34 = a.e13 * b.e23;
    float t35 = a.e13 * b.e0123;
    float t36 = a.e23 * b.scalar;
    float t37 = a.e23 * b.e01;
    float t38 = a.e23 * b.e02;
    float t39 = a.e23 * b.e12;
    float t40 = a.e23 * b.e03;
    float t41 = a.e23 * b.e13;
    float t42 = a.e23 * b.e23;
    float t43 = a.e23 * b.e0123;
    float t44 = a.e0123 * b.scalar;
    float t45 = a.e0123 * b.e12;
    float t46 = a.e0123 * b.e13;
    float t47 = a.e0123 * b.e23;
    return pga3_Motor(
        ((t0 - t19) - t33) - t42,
        (((t1 + t8) - t13) + t18) - (((t26 - t32) + t43) + t47),
        (((t2 + t9) + t12) - t17) - (((t27 - t35) - t40) - t46),
        ((t3 + t16) - t34) + t41,
        (((t4 + t10) + t15) - t23) + (((t24 - t29) - t38) - t45),
        ((t5 + t22) + t28) - t39,
        ((t6 - t21) + t31) + t36,
        (((t7 + t11) - t14) + t20) + (((t25 - t30) + t37) + t44)
    );
}

// `gp` of a Motor and a Point.
pga3_Odd pga3_motor_gp_point(pga3_Motor a, pga3_Point b) {
    float t0 = a.scalar * b.e012;
    float t1 = a.scalar * b.e013;
    float t2 = a.scalar * b.e023;
    float t3 = a.scalar * b.e123;
    float t4 = a.e01 * b.e123;
    float t5 = a.e02 * b.e123;
    float t6 = a.e12 * b.e012;
    float t7 = a.e12 * b.e013;
    float t8 = a.e12 * b.e023;
    float t9 = a.e12 * b.e123;
    float t10 = a.e03 * b.e123;
    float t11 = a.e13 * b.e012;
    float t12 = a.e13 * b.e013;
    float t13 = a.e13 * b.e023;
    float t14 = a.e13 * b.e123;
    float t15 = a.e23 * b.e012;
    float t16 = a.e23 * b.e013;
    float t17 = a.e23 * b.e023;
    float t18 = a.e23 * b.e123;
    float t19 = a.e0123 * b.e123;
    return pga3_Odd(
        (((-t6) - t12) - t17) - t19,
        -t18,
        t14,
        -t9,
        ((t0 + t10) - t13) + t16,
        ((t1 - t5) + t8) - t15,
        ((t2 + t4) - t7) + t11,
        t3
    );
}

// `gp` of a Motor and a Line.
pga3_Motor pga3_motor_gp_line(pga3_Motor a, pga3_Line b) {
    float t0 = a.scalar * b.e01;
    float t1 = a.scalar * b.e02;
    float t2 = a.scalar * b.e12;
    float t3 = a.scalar * b.e03;
    float t4 = a.scalar * b.e13;
    float t5 = a.scalar * b.e23;
    float t6 = a.e01 * b.e12;
    float t7 = a.e01 * b.e13;
    float t8 = a.e01 * b.e23;
    float t9 = a.e02 * b.e12;
    float t10 = a.e02 * b.e13;
    float t11 = a.e02 * b.e23;
    float t12 = a.e12 * b.e01;
    float t13 = a.e12 * b.e02;
    float t14 = a.e12 * b.e12;
    float t15 = a.e12 * b.e03;
    float t16 = a.e12 * b.e13;
    float t17 = a.e12 * b.e23;
    float t18 = a.e03 * b.e12;
    float t19 = a.e03 * b.e13;
    float t20 = a.e03 * b.e23;
    float t21 = a.e13 * b.e01;
    float t22 = a.e13 * b.e02;
    float t23 = a.e13 * b.e12;
    float t24 = a.e13 * b.e03;
    float t25 = a.e13 * b.e13;
    float t26 = a.e13 * b.e23;
    float t27 = a.e23 * b.e01;
    float t28 = a.e23 * b.e02;
    float t29 = a.e23 * b.e12;
    float t30 = a.e23 * b.e03;
    float t31 = a.e23 * b.e13;
    float t32 = a.e23 * b.e23;
    float t33 = a.e0123 * b.e12;
    float t34 = a.e0123 * b.e13;
    float t35 = a.e0123 * b.e23;
    return pga3_Motor(
        ((-t14) - t25) - t32,
        (((t0 - t9) + t13) - t19) + (t24 - t35),
        (((t1 + t6) - t12) - t20) + (t30 + t34),
        (t2 - t26) + t31,
        (((t3 + t7) + t11) - t21) - (t28 + t33),
        (t4 + t17) - t29,
        (t5 - t16) + t23,
        (((t8 - t10) + t15) + t18) - (t22 - t27)
    );
}

// `gp` of a Point and a Motor.
pga3_Odd pga3_point_gp_motor(pga3_Point a, pga3_Motor b) {
    float t0 = a.e012 * b.scalar;
    float t1 = a.e012 * b.e12;
    float t2 = a.e012 * b.e13;
    float t3 = a.e012 * b.e23;
    float t4 = a.e013 * b.scalar;
    float t5 = a.e013 * b.e12;
    float t6 = a.e013 * b.e13;
    float t7 = a.e013 * b.e23;
    float t8 = a.e023 * b.scalar;
    float t9 = a.e023 * b.e12;
    float t10 = a.e023 * b.e13;
    float t11 = a.e023 * b.e23;
    float t12 = a.e123 * b.scalar;
    float t13 = a.e123 * b.e01;
    float t14 = a.e123 * b.e02;
    float t15 = a.e123 * b.e12;
    float t16 = a.e123 * b.e03;
    float t17 = a.e123 * b.e13;
    float t18 = a.e123 * b.e23;
    float t19 = a.e123 * b.e0123;
    return pga3_Odd(
        ((t19 - t6) - t11) - t1,
        -t18,
        t17,
        -t15,
        ((t0 - t7) + t10) - t16,
        ((t3 + t4) - t9) + t14,
        ((t5 - t2) + t8) - t13,
        t12
    );
}

// `gp` of a Point and a Point.
pga3_Motor pga3_point_gp_point(pga3_Point a, pga3_Point b) {
    float t0 = a.e012 * b.e123;
    float t1 = a.e013 * b.e123;
    float t2 = a.e023 * b.e123;
    float t3 = a.e123 * b.e012;
    float t4 = a.e123 * b.e013;
    float t5 = a.e123 * b.e023;
    float t6 = a.e123 * b.e123;
    return pga3_Motor(
        -t6,
        t5 - t2,
        t1 - t4,
        0.0,
        t3 - t0,
        0.0,
        0.0,
        0.0
    );
}

// `gp` of a Point and a Line.
pga3_Odd pga3_point_gp_line(pga3_Point a, pga3_Line b) {
    float t0 = a.e012 * b.e12;
    float t1 = a.e012 * b.e13;
    float t2 = a.e012 * b.e23;
    float t3 = a.e013 * b.e12;
    float t4 = a.e013 * b.e13;
    float t5 = a.e013 * b.e23;
    float t6 = a.e023 * b.e12;
    float t7 = a.e023 * b.e13;
    float t8 = a.e023 * b.e23;
    float t9 = a.e123 * b.e01;
    float t10 = a.e123 * b.e02;
    float t11 = a.e123 * b.e12;
    float t12 = a.e123 * b.e03;
    float t13 = a.e123 * b.e13;
    float t14 = a.e123 * b.e23;
    return pga3_Odd(
        ((-t0) - t4) - t8,
        -t14,
        t13,
        -t11,
        (t7 - t5) - t12,
        (t2 - t6) + t10,
        (t3 - t1) - t9,
        0.0
    );
}

// `gp` of a Line and a Motor.
pga3_Motor pga3_line_gp_motor(pga3_Line a, pga3_Motor b) {
    float t0 = a.e01 * b.scalar;
    float t1 = a.e01 * b.e12;
    float t2 = a.e01 * b.e13;
    float t3 = a.e01 * b.e23;
    float t4 = a.e02 * b.scalar;
    float t5 = a.e02 * b.e12;
    float t6 = a.e02 * b.e13;
    float t7 = a.e02 * b.e23;
    float t8 = a.e12 * b.scalar;
    float t9 = a.e12 * b.e01;
    float t10 = a.e12 * b.e02;
    float t11 = a.e12 * b.e12;
    float t12 = a.e12 * b.e03;
    float t13 = a.e12 * b.e13;
    float t14 = a.e12 * b.e23;
    float t15 = a.e12 * b.e0123;
    float t16 = a.e03 * b.scalar;
    float t17 = a.e03 * b.e12;
    float t18 = a.e03 * b.e13;
    float t19 = a.e03 * b.e23;
    float t20 = a.e13 * b.scalar;
    float t21 = a.e13 * b.e01;
    float t22 = a.e13 * b.e02;
    float t23 = a.e13 * b.e12;
    float t24 = a.e13 * b.e03;
    float t25 = a.e13 * b.e13;
    float t26 = a.e13 * b.e23;
    float t27 = a.e13 * b.e0123;
    float t28 = a.e23 * b.scalar;
    float t29 = a.e23 * b.e01;
    float t30 = a.e23 * b.e02;
    float t31 = a.e23 * b.e12;
    float t32 = a.e23 * b.e03;
    float t33 = a.e23 * b.e13;
    float t34 = a.e23 * b.e23;
    float t35 = a.e23 * b.e0123;
    return pga3_Motor(
        ((-t11) - t25) - t34,
        (((t0 - t5) + t10) - t18) + (t24 - t35),
        (((t1 + t4) - t9) - t19) + (t27 + t32),
        (t8 - t26) + t33,
        (((t2 + t7) - t15) + t16) - (t21 + t30),
        (t14 + t20) - t31,
        (t23 - t13) + t28,
        (((t3 - t6) + t12) + t17) - (t22 - t29)
    );
}

// `gp` of a Line and a Point.
pga3_Odd pga3_line_gp_point(pga3_Line a, pga3_Point b) {
    float t0 = a.e01 * b.e123;
    float t1 = a.e02 * b.e123;
    float t2 = a.e12 * b.e012;
    float t3 = a.e12 * b.e013;
    float t4 = a.e12 * b.e023;
    float t5 = a.e12 * b.e123;
    float t6 = a.e03 * b.e123;
    float t7 = a.e13 * b.e012;
    float t8 = a.e13 * b.e013;
    float t9 = a.e13 * b.e023;
    float t10 = a.e13 * b.e123;
    float t11 = a.e23 * b.e012;
    float t12 = a.e23 * b.e013;
    float t13 = a.e23 * b.e023;
    float t14 = a.e23 * b.e123;
    return pga3_Odd(
        ((-t2) - t8) - t13,
        -t14,
        t10,
        -t5,
        (t6 - t9) + t12,
        (t4 - t1) - t11,
        (t0 - t3) + t7,
        0.0
    );
}

// `gp` of a Line and a Line.
pga3_Motor pga3_line_gp_line(pga3_Line a, pga3_Line b) {
    float t0 = a.e01 * b.e12;
    float t1 = a.e01 * b.e13;
    float t2 = a.e01 * b.e23;
    float t3 = a.e02 * b.e12;
    float t4 = a.e02 * b.e13;
    float t5 = a.e02 * b.e23;
    float t6 = a.e12 * b.e01;
    float t7 = a.e12 * b.e02;
    float t8 = a.e12 * b.e12;
    float t9 = a.e12 * b.e03;
    float t10 = a.e12 * b.e13;
    float t11 = a.e12 * b.e23;
    float t12 = a.e03 * b.e12;
    float t13 = a.e03 * b.e13;
    float t14 = a.e03 * b.e23;
    float t15 = a.e13 * b.e01;
    float t16 = a.e13 * b.e02;
    float t17 = a.e13 * b.e12;
    float t18 = a.e13 * b.e03;
    float t19 = a.e13 * b.e13;
    float t20 = a.e13 * b.e23;
    float t21 = a.e23 * b.e01;
    float t22 = a.e23 * b.e02;
    float t23 = a.e23 * b.e12;
    float t24 = a.e23 * b.e03;
    float t25 = a.e23 * b.e13;
    float t26 = a.e23 * b.e23;
    return pga3_Motor(
        ((-t8) - t19) - t26,
        ((t7 - t3) - t13) + t18,
        ((t0 - t6) - t14) + t24,
        t25 - t20,
        ((t1 + t5) - t15) - t22,
        t11 - t23,
        t17 - t10,
        (((t2 - t4) + t9) + t12) - (t16 - t21)
    );
}

// The reverse of a Motor.
pga3_Motor pga3_motor_reverse(pga3_Motor x) {
    return pga3_Motor(
        x.scalar,
        -x.e01,
        -x.e02,
        -x.e12,
        -x.e03,
        -x.e13,
        -x.e23,
        x.e0123
    );
}

// The squared norm <x rev(x)>_0 of a Motor (may be negative or zero).
float pga3_motor_norm_squared(pga3_Motor x) {
    float t0 = x.scalar * x.scalar;
    float t1 = x.e12 * x.e12;
    float t2 = x.e13 * x.e13;
    float t3 = x.e23 * x.e23;
    return ((t0 + t1) + t2) + t3;
}

// The reverse of a Point.
pga3_Point pga3_point_reverse(pga3_Point x) {
    return pga3_Point(
        -x.e012,
        -x.e013,
        -x.e023,
        -x.e123
    );
}

// The squared norm <x rev(x)>_0 of a Point (may be negative or zero).
float pga3_point_norm_squared(pga3_Point x) {
    float t0 = x.e123 * x.e123;
    return t0;
}

// The reverse of a Line.
pga3_Line pga3_line_reverse(pga3_Line x) {
    return pga3_Line(
        -x.e01,
        -x.e02,
        -x.e12,
        -x.e03,
        -x.e13,
        -x.e23
    );
}

// The squared norm <x rev(x)>_0 of a Line (may be negative or zero).
float pga3_line_norm_squared(pga3_Line x) {
    float t0 = x.e12 * x.e12;
    float t1 = x.e13 * x.e13;
    float t2 = x.e23 * x.e23;
    return (t0 + t1) + t2;
}

// S x rev(S) for a Motor S and a Motor x, in one fused kernel.
pga3_Motor pga3_motor_apply_motor(pga3_Motor s, pga3_Motor x) {
    float t0 = ((s.scalar * x.scalar) - (s.e12 * x.e12)) - ((s.e13 * x.e13) + (s.e23 * x.e23));
    float t1 = (((s.scalar * x.e01) + (s.e01 * x.scalar)) - ((s.e02 * x.e12) - (s.e12 * x.e02))) - (((s.e03 * x.e13) - (s.e13 * x.e03)) + ((s.e23 * x.e0123) + (s.e0123 * x.e23)));
    float t2 = (((s.scalar * x.e02) + (s.e01 * x.e12)) + ((s.e02 * x.scalar) - (s.e12 * x.e01))) - (((s.e03 * x.e23) - (s.e13 * x.e0123)) - ((s.e23 * x.e03) + (s.e0123 * x.e13)));
    float t3 = ((s.scalar * x.e12) + (s.e12 * x.scalar)) - ((s.e13 * x.e23) - (s.e23 * x.e13));
    float t4 = (((s.scalar * x.e03) + (s.e01 * x.e13)) + ((s.e02 * x.e23) - (s.e12 * x.e0123))) + (((s.e03 * x.scalar) - (s.e13 * x.e01)) - ((s.e23 * x.e02) + (s.e0123 * x.e12)));
    float t5 = ((s.scalar * x.e13) + (s.e12 * x.e23)) + ((s.e13 * x.scalar) - (s.e23 * x.e12));
    float t6 = ((s.scalar * x.e23) - (s.e12 * x.e13)) + ((s.e13 * x.e12) + (s.e23 * x.scalar));
    float t7 = (((s.scalar * x.e0123) + (s.e01 * x.e23)) - ((s.e02 * x.e13) - (s.e12 * x.e03))) + (((s.e03 * x.e12) - (s.e13 * x.e02)) + ((s.e23 * x.e01) + (s.e0123 * x.scalar)));
    return pga3_Motor(
        ((t0 * s.scalar) + (t3 * s.e12)) + ((t5 * s.e13) + (t6 * s.e23)),
        (((t1 * s.scalar) - (t0 * s.e01)) - ((t3 * s.e02) - (t2 * s.e12))) - (((t5 * s.e03) - (t4 * s.e13)) - ((t7 * s.e23) - (t6 * s.e0123))),
        (((t2 * s.scalar) + (t3 * s.e01)) - ((t0 * s.e02) + (t1 * s.e12))) - (((t6 * s.e03) + (t7 * s.e13)) - ((t4 * s.e23) + (t5 * s.e0123))),
        ((t3 * s.scalar) - (t0 * s.e12)) - ((t6 * s.e13) - (t5 * s.e23)),
        (((t4 * s.scalar) + (t5 * s.e01)) + ((t6 * s.e02) + (t7 * s.e12))) - (((t0 * s.e03) + (t1 * s.e13)) + ((t2 * s.e23) + (t3 * s.e0123))),
        ((t5 * s.scalar) + (t6 * s.e12)) - ((t0 * s.e13) + (t3 * s.e23)),
        ((t6 * s.scalar) - (t5 * s.e12)) + ((t3 * s.e13) - (t0 * s.e23)),
        (((t7 * s.scalar) - (t6 * s.e01)) + ((t5 * s.e02) - (t4 * s.e12))) - (((t3 * s.e03) - (t2 * s.e13)) + ((t1 * s.e23) - (t0 * s.e0123)))
    );
}

// S x rev(S) for a Motor S and a Point x, in one fused kernel.
pga3_Point pga3_motor_apply_point(pga3_Motor s, pga3_Point x) {
    float t0 = (-s.e0123) * x.e123;
    float t1 = (s.e03 * x.e123) - ((s.e13 * x.e023) + ((-s.e23) * x.e013));
    float t2 = -((s.e02 * x.e123) - ((s.e12 * x.e023) + ((-s.e23) * x.e012)));
    float t3 = (s.e01 * x.e123) - ((s.e12 * x.e013) - (s.e13 * x.e012));
    float t4 = ((s.scalar * s.scalar) + (s.e23 * s.e23)) + ((s.e12 * s.e12) + (s.e13 * s.e13));
    float t5 = (((t1 * s.scalar) - (t0 * s.e12)) - (t3 * s.e13)) - (t2 * (-s.e23));
    float t6 = (((t2 * s.scalar) + (t3 * s.e12)) + (t1 * (-s.e23))) - (t0 * s.e13);
    float t7 = (((t3 * s.scalar) + (t1 * s.e13)) + (t0 * (-s.e23))) - (t2 * s.e12);
    return pga3_Point(
        (t4 * x.e012) + (t5 + t5),
        (t4 * x.e013) + (t6 + t6),
        (t4 * x.e023) + (t7 + t7),
        t4 * x.e123
    );
}

// S x rev(S) for a Motor S and a Line x, in one fused kernel.
pga3_Line pga3_motor_apply_line(pga3_Motor s, pga3_Line x) {
    float t0 = -((s.e12 * x.e12) + ((s.e13 * x.e13) + (s.e23 * x.e23)));
    float t1 = ((s.scalar * x.e01) - ((s.e02 * x.e12) - (s.e12 * x.e02))) - ((s.e03 * x.e13) - ((s.e13 * x.e03) - (s.e0123 * x.e23)));
    float t2 = ((s.scalar * x.e02) + ((s.e01 * x.e12) - (s.e12 * x.e01))) - ((s.e03 * x.e23) - ((s.e23 * x.e03) + (s.e0123 * x.e13)));
    float t3 = (s.scalar * x.e12) - ((s.e13 * x.e23) - (s.e23 * x.e13));
    float t4 = ((s.scalar * x.e03) + ((s.e01 * x.e13) + (s.e02 * x.e23))) - ((s.e13 * x.e01) + ((s.e23 * x.e02) + (s.e0123 * x.e12)));
    float t5 = (s.scalar * x.e13) + ((s.e12 * x.e23) - (s.e23 * x.e12));
    float t6 = (s.scalar * x.e23) - ((s.e12 * x.e13) - (s.e13 * x.e12));
    float t7 = ((s.e01 * x.e23) - ((s.e02 * x.e13) - (s.e12 * x.e03))) + ((s.e03 * x.e12) - ((s.e13 * x.e02) - (s.e23 * x.e01)));
    return pga3_Line(
        (((t1 * s.scalar) - (t0 * s.e01)) - ((t3 * s.e02) - (t2 * s.e12))) - (((t5 * s.e03) - (t4 * s.e13)) - ((t7 * s.e23) - (t6 * s.e0123))),
        (((t2 * s.scalar) + (t3 * s.e01)) - ((t0 * s.e02) + (t1 * s.e12))) - (((t6 * s.e03) + (t7 * s.e13)) - ((t4 * s.e23) + (t5 * s.e0123))),
        ((t3 * s.scalar) - (t0 * s.e12)) - ((t6 * s.e13) - (t5 * s.e23)),
        (((t4 * s.scalar) + (t5 * s.e01)) + ((t6 * s.e02) + (t7 * s.e12))) - (((t0 * s.e03) + (t1 * s.e13)) + ((t2 * s.e23) + (t3 * s.e0123))),
        ((t5 * s.scalar) + (t6 * s.e12)) - ((t0 * s.e13) + (t3 * s.e23)),
        ((t6 * s.scalar) - (t5 * s.e12)) + ((t3 * s.e13) - (t0 * s.e23))
    );
}

// S x rev(S) for a Point S and a Motor x, in one fused kernel.
pga3_Motor pga3_point_apply_motor(pga3_Point s, pga3_Motor x) {
    float t0 = s.e123 * x.e0123;
    float t1 = -((s.e013 * x.e23) - ((s.e023 * x.e13) - (s.e123 * x.e03)));
    float t2 = (s.e012 * x.e23) - ((s.e023 * x.e12) - (s.e123 * x.e02));
    float t3 = -((s.e012 * x.e13) - ((s.e013 * x.e12) - (s.e123 * x.e01)));
    float t4 = s.e123 * s.e123;
    float t5 = t3 * s.e123;
    float t6 = -(t2 * s.e123);
    float t7 = t1 * s.e123;
    float t8 = -(t0 * s.e123);
    return pga3_Motor(
        t4 * x.scalar,
        (t4 * x.e01) + (t5 + t5),
        (t4 * x.e02) + (t6 + t6),
        t4 * x.e12,
        (t4 * x.e03) + (t7 + t7),
        t4 * x.e13,
        t4 * x.e23,
        (t4 * x.e0123) + (t8 + t8)
    );
}

// S x rev(S) for a Point S and a Point x, in one fused kernel.
pga3_Point pga3_point_apply_point(pga3_Point s, pga3_Point x) {
    float t0 = -(s.e123 * x.e123);
    float t1 = -((s.e023 * x.e123) - (s.e123 * x.e023));
    float t2 = (s.e013 * x.e123) - (s.e123 * x.e013);
    float t3 = -((s.e012 * x.e123) - (s.e123 * x.e012));
    return pga3_Point(
        -((t0 * s.e012) + (t3 * s.e123)),
        (t2 * s.e123) - (t0 * s.e013),
        -((t0 * s.e023) + (t1 * s.e123)),
        -(t0 * s.e123)
    );
}

// S x rev(S) for a Point S and a Line x, in one fused kernel.
pga3_Line pga3_point_apply_line(pga3_Point s, pga3_Line x) {
    float t0 = -(s.e123 * x.e23);
    float t1 = s.e123 * x.e13;
    float t2 = -((s.e013 * x.e23) - ((s.e023 * x.e13) - (s.e123 * x.e03)));
    float t3 = -(s.e123 * x.e12);
    float t4 = (s.e012 * x.e23) - ((s.e023 * x.e12) - (s.e123 * x.e02));
    float t5 = -((s.e012 * x.e13) - ((s.e013 * x.e12) - (s.e123 * x.e01)));
    return pga3_Line(
        (t5 * s.e123) - ((t1 * s.e012) + (t3 * s.e013)),
        (t0 * s.e012) - ((t3 * s.e023) + (t4 * s.e123)),
        -(t3 * s.e123),
        (t0 * s.e013) + ((t1 * s.e023) + (t2 * s.e123)),
        t1 * s.e123,
        -(t0 * s.e123)
    );
}

// S x rev(S) for a Line S and a Motor x, in one fused kernel.
pga3_Motor pga3_line_apply_motor(pga3_Line s, pga3_Motor x) {
    float t0 = -((s.e12 * x.e12) + ((s.e13 * x.e13) + (s.e23 * x.e23)));
    float t1 = ((s.e01 * x.scalar) - ((s.e02 * x.e12) - (s.e12 * x.e02))) - ((s.e03 * x.e13) - ((s.e13 * x.e03) - (s.e23 * x.e0123)));
    float t2 = ((s.e01 * x.e12) + ((s.e02 * x.scalar) - (s.e12 * x.e01))) - ((s.e03 * x.e23) - ((s.e13 * x.e0123) + (s.e23 * x.e03)));
    float t3 = (s.e12 * x.scalar) - ((s.e13 * x.e23) - (s.e23 * x.e13));
    float t4 = ((s.e01 * x.e13) + ((s.e02 * x.e23) - (s.e12 * x.e0123))) + ((s.e03 * x.scalar) - ((s.e13 * x.e01) + (s.e23 * x.e02)));
    float t5 = (s.e12 * x.e23) + ((s.e13 * x.scalar) - (s.e23 * x.e12));
    float t6 = -((s.e12 * x.e13) - ((s.e13 * x.e12) + (s.e23 * x.scalar)));
    float t7 = ((s.e01 * x.e23) - ((s.e02 * x.e13) - (s.e12 * x.e03))) + ((s.e03 * x.e12) - ((s.e13 * x.e02) - (s.e23 * x.e01)));
    return pga3_Motor(
        (t3 * s.e12) + ((t5 * s.e13) + (t6 * s.e23)),
        ((t2 * s.e12) - ((t0 * s.e01) + (t3 * s.e02))) - ((t5 * s.e03) - ((t4 * s.e13) + (t7 * s.e23))),
        ((t3 * s.e01) - ((t0 * s.e02) + (t1 * s.e12))) - ((t6 * s.e03) + ((t7 * s.e13) - (t4 * s.e23))),
        (t5 * s.e23) - ((t0 * s.e12) + (t6 * s.e13)),
        ((t5 * s.e01) + ((t6 * s.e02) + (t7 * s.e12))) - ((t0 * s.e03) + ((t1 * s.e13) + (t2 * s.e23))),
        (t6 * s.e12) - ((t0 * s.e13) + (t3 * s.e23)),
        (t3 * s.e13) - ((t5 * s.e12) + (t0 * s.e23)),
        ((t5 * s.e02) - ((t6 * s.e01) + (t4 * s.e12))) - ((t3 * s.e03) - ((t2 * s.e13) - (t1 * s.e23)))
    );
}

// S x rev(S) for a Line S and a Point x, in one fused kernel.
pga3_Point pga3_line_apply_point(pga3_Line s, pga3_Point x) {
    float t0 = (s.e03 * x.e123) - ((s.e13 * x.e023) - (s.e23 * x.e013));
    float t1 = -((s.e02 * x.e123) - ((s.e12 * x.e023) - (s.e23 * x.e012)));
    float t2 = (s.e01 * x.e123) - ((s.e12 * x.e013) - (s.e13 * x.e012));
    float t3 = (s.e12 * s.e12) + ((s.e13 * s.e13) + (s.e23 * s.e23));
    float t4 = (t1 * s.e23) - (t2 * s.e13);
    float t5 = (t2 * s.e12) - (t0 * s.e23);
    float t6 = (t0 * s.e13) - (t1 * s.e12);
    return pga3_Point(
        (t3 * x.e012) + (t4 + t4),
        (t3 * x.e013) + (t5 + t5),
        (t3 * x.e023) + (t6 + t6),
        t3 * x.e123
    );
}

// S x rev(S) for a Line S and a Line x, in one fused kernel.
pga3_Line pga3_line_apply_line(pga3_Line s, pga3_Line x) {
    float t0 = -((s.e12 * x.e12) + ((s.e13 * x.e13) + (s.e23 * x.e23)));
    float t1 = -(((s.e02 * x.e12) - (s.e12 * x.e02)) + ((s.e03 * x.e13) - (s.e13 * x.e03)));
    float t2 = ((s.e01 * x.e12) - (s.e12 * x.e01)) - ((s.e03 * x.e23) - (s.e23 * x.e03));
    float t3 = -((s.e13 * x.e23) - (s.e23 * x.e13));
    float t4 = ((s.e01 * x.e13) + (s.e02 * x.e23)) - ((s.e13 * x.e01) + (s.e23 * x.e02));
    float t5 = (s.e12 * x.e23) - (s.e23 * x.e12);
    float t6 = -((s.e12 * x.e13) - (s.e13 * x.e12));
    float t7 = ((s.e01 * x.e23) - ((s.e02 * x.e13) - (s.e12 * x.e03))) + ((s.e03 * x.e12) - ((s.e13 * x.e02) - (s.e23 * x.e01)));
    return pga3_Line(
        ((t2 * s.e12) - ((t0 * s.e01) + (t3 * s.e02))) - ((t5 * s.e03) - ((t4 * s.e13) + (t7 * s.e23))),
        ((t3 * s.e01) - ((t0 * s.e02) + (t1 * s.e12))) - ((t6 * s.e03) + ((t7 * s.e13) - (t4 * s.e23))),
        (t5 * s.e23) - ((t0 * s.e12) + (t6 * s.e13)),
        ((t5 * s.e01) + ((t6 * s.e02) + (t7 * s.e12))) - ((t0 * s.e03) + ((t1 * s.e13) + (t2 * s.e23))),
        (t6 * s.e12) - ((t0 * s.e13) + (t3 * s.e23)),
        (t3 * s.e13) - ((t5 * s.e12) + (t0 * s.e23))
    );
}

// S x rev(S) for a unit Motor S (S rev(S) = 1) and a Motor x; not the action otherwise.
pga3_Motor pga3_motor_apply_unit_motor(pga3_Motor s, pga3_Motor x) {
    float t0 = -(((s.e02 * x.e12) - (s.e12 * x.e02)) + ((s.e03 * x.e13) - (s.e13 * x.e03)));
    float t1 = ((s.e01 * x.e12) - (s.e12 * x.e01)) - ((s.e03 * x.e23) - (s.e23 * x.e03));
    float t2 = -((s.e13 * x.e23) - (s.e23 * x.e13));
    float t3 = ((s.e01 * x.e13) + (s.e02 * x.e23)) - ((s.e13 * x.e01) + (s.e23 * x.e02));
    float t4 = (s.e12 * x.e23) - (s.e23 * x.e12);
    float t5 = -((s.e12 * x.e13) - (s.e13 * x.e12));
    float t6 = ((t0 * s.scalar) + ((t1 * s.e12) - (t2 * s.e02))) + ((t3 * s.e13) - ((t4 * s.e03) + (t5 * s.e0123)));
    float t7 = -(((t0 * s.e12) - ((t1 * s.scalar) + (t2 * s.e01))) - ((t3 * s.e23) + ((t4 * s.e0123) - (t5 * s.e03))));
    float t8 = (t2 * s.scalar) + ((t4 * s.e23) - (t5 * s.e13));
    float t9 = -(((t0 * s.e13) + ((t1 * s.e23) + (t2 * s.e0123))) - ((t3 * s.scalar) + ((t4 * s.e01) + (t5 * s.e02))));
    float t10 = -((t2 * s.e23) - ((t4 * s.scalar) + (t5 * s.e12)));
    float t11 = (t2 * s.e13) - ((t4 * s.e12) - (t5 * s.scalar));
    return pga3_Motor(
        x.scalar,
        (x.e01 + t6) + t6,
        (x.e02 + t7) + t7,
        (x.e12 + t8) + t8,
        (x.e03 + t9) + t9,
        (x.e13 + t10) + t10,
        (x.e23 + t11) + t11,
        x.e0123
    );
}

// S x rev(S) for a unit Motor S (S rev(S) = 1) and a Point x; not the action otherwise.
pga3_Point pga3_motor_apply_unit_point(pga3_Motor s, pga3_Point x) {
    float t0 = -(s.e0123 * x.e123);
    float t1 = (s.e03 * x.e123) - ((s.e13 * x.e023) - (s.e23 * x.e013));
    float t2 = -((s.e02 * x.e123) - ((s.e12 * x.e023) - (s.e23 * x.e012)));
    float t3 = (s.e01 * x.e123) - ((s.e12 * x.e013) - (s.e13 * x.e012));
    float t4 = -(((t0 * s.e12) - (t1 * s.scalar)) - ((t2 * s.e23) - (t3 * s.e13)));
    float t5 = -(((t0 * s.e13) + (t1 * s.e23)) - ((t2 * s.scalar) + (t3 * s.e12)));
    float t6 = -(((t0 * s.e23) - (t1 * s.e13)) + ((t2 * s.e12) - (t3 * s.scalar)));
    return pga3_Point(
        (x.e012 + t4) + t4,
        (x.e013 + t5) + t5,
        (x.e023 + t6) + t6,
        x.e123
    );
}

// S x rev(S) for a unit Motor S (S rev(S) = 1) and a Line x; not the action otherwise.
pga3_Line pga3_motor_apply_unit_line(pga3_Motor s, pga3_Line x) {
    float t0 = -(((s.e02 * x.e12) - (s.e12 * x.e02)) + ((s.e03 * x.e13) - (s.e13 * x.e03)));
    float t1 = ((s.e01 * x.e12) - (s.e12 * x.e01)) - ((s.e03 * x.e23) - (s.e23 * x.e03));
    float t2 = -((s.e13 * x.e23) - (s.e23 * x.e13));
    float t3 = ((s.e01 * x.e13) + (s.e02 * x.e23)) - ((s.e13 * x.e01) + (s.e23 * x.e02));
    float t4 = (s.e12 * x.e23) - (s.e23 * x.e12);
    float t5 = -((s.e12 * x.e13) - (s.e13 * x.e12));
    float t6 = ((t0 * s.scalar) + ((t1 * s.e12) - (t2 * s.e02))) + ((t3 * s.e13) - ((t4 * s.e03) + (t5 * s.e0123)));
    float t7 = -(((t0 * s.e12) - ((t1 * s.scalar) + (t2 * s.e01))) - ((t3 * s.e23) + ((t4 * s.e0123) - (t5 * s.e03))));
    float t8 = (t2 * s.scalar) + ((t4 * s.e23) - (t5 * s.e13));
    float t9 = -(((t0 * s.e13) + ((t1 * s.e23) + (t2 * s.e0123))) - ((t3 * s.scalar) + ((t4 * s.e01) + (t5 * s.e02))));
    float t10 = -((t2 * s.e23) - ((t4 * s.scalar) + (t5 * s.e12)));
    float t11 = (t2 * s.e13) - ((t4 * s.e12) - (t5 * s.scalar));
    return pga3_Line(
        (x.e01 + t6) + t6,
        (x.e02 + t7) + t7,
        (x.e12 + t8) + t8,
        (x.e03 + t9) + t9,
        (x.e13 + t10) + t10,
        (x.e23 + t11) + t11
    );
}

// S x rev(S) for a unit Point S (S rev(S) = 1) and a Motor x; not the action otherwise.
pga3_Motor pga3_point_apply_unit_motor(pga3_Point s, pga3_Motor x) {
    float t0 = s.e123 * x.e0123;
    float t1 = -((s.e013 * x.e23) - ((s.e023 * x.e13) - (s.e123 * x.e03)));
    float t2 = (s.e012 * x.e23) - ((s.e023 * x.e12) - (s.e123 * x.e02));
    float t3 = -((s.e012 * x.e13) - ((s.e013 * x.e12) - (s.e123 * x.e01)));
    float t4 = t3 * s.e123;
    float t5 = -(t2 * s.e123);
    float t6 = t1 * s.e123;
    float t7 = -(t0 * s.e123);
    return pga3_Motor(
        x.scalar,
        (x.e01 + t4) + t4,
        (x.e02 + t5) + t5,
        x.e12,
        (x.e03 + t6) + t6,
        x.e13,
        x.e23,
        (x.e0123 + t7) + t7
    );
}

// S x rev(S) for a unit Point S (S rev(S) = 1) and a Point x; not the action otherwise.
pga3_Point pga3_point_apply_unit_point(pga3_Point s, pga3_Point x) {
    float t0 = -((s.e023 * x.e123) - (s.e123 * x.e023));
    float t1 = (s.e013 * x.e123) - (s.e123 * x.e013);
    float t2 = -((s.e012 * x.e123) - (s.e123 * x.e012));
    float t3 = -(t2 * s.e123);
    float t4 = t1 * s.e123;
    float t5 = -(t0 * s.e123);
    return pga3_Point(
        (x.e012 + t3) + t3,
        (x.e013 + t4) + t4,
        (x.e023 + t5) + t5,
        x.e123
    );
}

// S x rev(S) for a unit Point S (S rev(S) = 1) and a Line x; not the action otherwise.
pga3_Line pga3_point_apply_unit_line(pga3_Point s, pga3_Line x) {
    float t0 = -((s.e013 * x.e23) - ((s.e023 * x.e13) - (s.e123 * x.e03)));
    float t1 = (s.e012 * x.e23) - ((s.e023 * x.e12) - (s.e123 * x.e02));
    float t2 = -((s.e012 * x.e13) - ((s.e013 * x.e12) - (s.e123 * x.e01)));
    float t3 = t2 * s.e123;
    float t4 = -(t1 * s.e123);
    float t5 = t0 * s.e123;
    return pga3_Line(
        (x.e01 + t3) + t3,
        (x.e02 + t4) + t4,
        x.e12,
        (x.e03 + t5) + t5,
        x.e13,
        x.e23
    );
}

// S x rev(S) for a unit Line S (S rev(S) = 1) and a Motor x; not the action otherwise.
pga3_Motor pga3_line_apply_unit_motor(pga3_Line s, pga3_Motor x) {
    float t0 = -(((s.e02 * x.e12) - (s.e12 * x.e02)) + ((s.e03 * x.e13) - (s.e13 * x.e03)));
    float t1 = ((s.e01 * x.e12) - (s.e12 * x.e01)) - ((s.e03 * x.e23) - (s.e23 * x.e03));
    float t2 = -((s.e13 * x.e23) - (s.e23 * x.e13));
    float t3 = ((s.e01 * x.e13) + (s.e02 * x.e23)) - ((s.e13 * x.e01) + (s.e23 * x.e02));
    float t4 = (s.e12 * x.e23) - (s.e23 * x.e12);
    float t5 = -((s.e12 * x.e13) - (s.e13 * x.e12));
    float t6 = ((t1 * s.e12) - (t2 * s.e02)) + ((t3 * s.e13) - (t4 * s.e03));
    float t7 = -(((t0 * s.e12) - (t2 * s.e01)) - ((t3 * s.e23) - (t5 * s.e03)));
    float t8 = (t4 * s.e23) - (t5 * s.e13);
    float t9 = -(((t0 * s.e13) + (t1 * s.e23)) - ((t4 * s.e01) + (t5 * s.e02)));
    float t10 = -((t2 * s.e23) - (t5 * s.e12));
    float t11 = (t2 * s.e13) - (t4 * s.e12);
    return pga3_Motor(
        x.scalar,
        (x.e01 + t6) + t6,
        (x.e02 + t7) + t7,
        (x.e12 + t8) + t8,
        (x.e03 + t9) + t9,
        (x.e13 + t10) + t10,
        (x.e23 + t11) + t11,
        x.e0123
    );
}

// S x rev(S) for a unit Line S (S rev(S) = 1) and a Point x; not the action otherwise.
pga3_Point pga3_line_apply_unit_point(pga3_Line s, pga3_Point x) {
    float t0 = (s.e03 * x.e123) - ((s.e13 * x.e023) - (s.e23 * x.e013));
    float t1 = -((s.e02 * x.e123) - ((s.e12 * x.e023) - (s.e23 * x.e012)));
    float t2 = (s.e01 * x.e123) - ((s.e12 * x.e013) - (s.e13 * x.e012));
    float t3 = (t1 * s.e23) - (t2 * s.e13);
    float t4 = -((t0 * s.e23) - (t2 * s.e12));
    float t5 = (t0 * s.e13) - (t1 * s.e12);
    return pga3_Point(
        (x.e012 + t3) + t3,
        (x.e013 + t4) + t4,
        (x.e023 + t5) + t5,
        x.e123
    );
}

// S x rev(S) for a unit Line S (S rev(S) = 1) and a Line x; not the action otherwise.
pga3_Line pga3_line_apply_unit_line(pga3_Line s, pga3_Line x) {
    float t0 = -(((s.e02 * x.e12) - (s.e12 * x.e02)) + ((s.e03 * x.e13) - (s.e13 * x.e03)));
    float t1 = ((s.e01 * x.e12) - (s.e12 * x.e01)) - ((s.e03 * x.e23) - (s.e23 * x.e03));
    float t2 = -((s.e13 * x.e23) - (s.e23 * x.e13));
    float t3 = ((s.e01 * x.e13) + (s.e02 * x.e23)) - ((s.e13 * x.e01) + (s.e23 * x.e02));
    float t4 = (s.e12 * x.e23) - (s.e23 * x.e12);
    float t5 = -((s.e12 * x.e13) - (s.e13 * x.e12));
    float t6 = ((t1 * s.e12) - (t2 * s.e02)) + ((t3 * s.e13) - (t4 * s.e03));
    float t7 = -(((t0 * s.e12) - (t2 * s.e01)) - ((t3 * s.e23) - (t5 * s.e03)));
    float t8 = (t4 * s.e23) - (t5 * s.e13);
    float t9 = -(((t0 * s.e13) + (t1 * s.e23)) - ((t4 * s.e01) + (t5 * s.e02)));
    float t10 = -((t2 * s.e23) - (t5 * s.e12));
    float t11 = (t2 * s.e13) - (t4 * s.e12);
    return pga3_Line(
        (x.e01 + t6) + t6,
        (x.e02 + t7) + t7,
        (x.e12 + t8) + t8,
        (x.e03 + t9) + t9,
        (x.e13 + t10) + t10,
        (x.e23 + t11) + t11
    );
}

// exp of a Line: a unit Motor (closed form; non-finite input gives non-finite output).
pga3_Motor pga3_line_exp(pga3_Line x) {
    float t0 = ((x.e12 * x.e12) + (x.e13 * x.e13)) + (x.e23 * x.e23);
    vec3 t1 = pga3_exp_factors(t0);
    float t2 = ((x.e01 * x.e23) - (x.e02 * x.e13)) + (x.e12 * x.e03);
    float t3 = t2 * t1.y;
    return pga3_Motor(
        t1.z,
        (t1.x * x.e01) + (t3 * x.e23),
        (t1.x * x.e02) - (t3 * x.e13),
        t1.x * x.e12,
        (t1.x * x.e03) + (t3 * x.e12),
        t1.x * x.e13,
        t1.x * x.e23,
        t2 * t1.x
    );
}

// log of a unit Motor (m rev(m) = 1): the Line B with exp(B) = m, angle in [0, pi); a full turn gives non-finite output.
pga3_Line pga3_motor_log_unit(pga3_Motor x) {
    float t0 = sqrt(((x.e12 * x.e12) + (x.e13 * x.e13)) + (x.e23 * x.e23));
    vec3 t1 = pga3_log_factors(t0, x.scalar);
    float t2 = x.e0123 * t1.y;
    return pga3_Line(
        (t1.x * x.e01) - (t2 * x.e23),
        (t1.x * x.e02) + (t2 * x.e13),
        t1.x * x.e12,
        (t1.x * x.e03) - (t2 * x.e12),
        t1.x * x.e13,
        t1.x * x.e23
    );
}

// m / sqrt(m rev(m)) for a Motor: a unit Motor; a non-positive norm gives non-finite output.
pga3_Motor pga3_motor_normalize(pga3_Motor x) {
    float t0 = (x.scalar * x.scalar) - (((-(x.e12 * x.e12)) - (x.e13 * x.e13)) - (x.e23 * x.e23));
    float t1 = 1.0 / t0;
    float t2 = (x.scalar * x.e0123) - (((x.e01 * x.e23) - (x.e02 * x.e13)) + (x.e12 * x.e03));
    float t3 = sqrt(t1);
    float t4 = (-(t2 * t3)) * t1;
    return pga3_Motor(
        x.scalar * t3,
        (x.e01 * t3) + (-(t4 * x.e23)),
        (x.e02 * t3) + (t4 * x.e13),
        x.e12 * t3,
        (x.e03 * t3) + (-(t4 * x.e12)),
        x.e13 * t3,
        x.e23 * t3,
        (x.e0123 * t3) + (x.scalar * t4)
    );
}

