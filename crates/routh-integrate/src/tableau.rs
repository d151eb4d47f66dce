//! Butcher tableau of the explicit Runge–Kutta pair DOP853 of Dormand & Prince,
//! with the coefficients of its 7th-order continuous extension.
//!
//! Source: E. Hairer, S. P. Nørsett, G. Wanner, *Solving Ordinary Differential
//! Equations I. Nonstiff Problems*, 2nd ed., Springer (1993), Section II.6 and
//! II.10; the numerical values are those of the `PARAMETER` statements in
//! Hairer's Fortran code `dop853.f` (version of April 25, 1996, small corrections
//! March 4, 2002), transcribed as plain data.
//!
//! Stages are numbered from 0 here (Hairer numbers them from 1):
//! * stages 0..=11 are the twelve stages of the 8th-order step;
//! * stage 12 is `f(t + h, y_new)`, the derivative at the new point, which is
//!   also the first stage of the next step (FSAL); its row of [`A`] is [`B`];
//! * stages 13..=15 are the three extra stages of the dense output.

// The literals are transcribed digit for digit from the published code.
#![allow(clippy::excessive_precision)]

/// Nodes `c_i` of the sixteen stages (stage 12 is the new point, `c = 1`).
pub const C: [f64; 16] = [
    0.0,
    0.526001519587677318785587544488e-01,
    0.789002279381515978178381316732e-01,
    0.118350341907227396726757197510e+00,
    0.281649658092772603273242802490e+00,
    0.333333333333333333333333333333e+00,
    0.25e+00,
    0.307692307692307692307692307692e+00,
    0.651282051282051282051282051282e+00,
    0.6e+00,
    0.857142857142857142857142857142e+00,
    1.0,
    1.0,
    0.1e+00,
    0.2e+00,
    0.777777777777777777777777777778e+00,
];

/// Weights `b_i` of the 8th-order solution (nonzero at stages 0 and 5..=11).
pub const B: [f64; 12] = [
    5.42937341165687622380535766363e-2,
    0.0,
    0.0,
    0.0,
    0.0,
    4.45031289275240888144113950566e0,
    1.89151789931450038304281599044e0,
    -5.8012039600105847814672114227e0,
    3.1116436695781989440891606237e-1,
    -1.52160949662516078556178806805e-1,
    2.01365400804030348374776537501e-1,
    4.47106157277725905176885569043e-2,
];

/// Weights of the 3rd-order embedded estimate: `b - BHH` is the 3rd-order error,
/// with `BHH` nonzero at stages 0, 8 and 11 only.
pub const BHH: [f64; 12] = [
    0.244094488188976377952755905512e+00,
    0.0,
    0.0,
    0.0,
    0.0,
    0.0,
    0.0,
    0.0,
    0.733846688281611857341361741547e+00,
    0.0,
    0.0,
    0.220588235294117647058823529412e-01,
];

/// Weights `b - b̂` of the 5th-order error estimate (nonzero at stages 0 and 5..=11).
pub const ER: [f64; 12] = [
    0.1312004499419488073250102996e-01,
    0.0,
    0.0,
    0.0,
    0.0,
    -0.1225156446376204440720569753e+01,
    -0.4957589496572501915214079952e+00,
    0.1664377182454986536961530415e+01,
    -0.3503288487499736816886487290e+00,
    0.3341791187130174790297318841e+00,
    0.8192320648511571246570742613e-01,
    -0.2235530786388629525884427845e-01,
];

const Z: f64 = 0.0;

/// Runge–Kutta matrix `a_ij` for all sixteen stages (row `i` gives stage `i`;
/// strictly lower triangular). Row 12 equals [`B`] padded with zeros.
pub const A: [[f64; 16]; 16] = [
    [Z, Z, Z, Z, Z, Z, Z, Z, Z, Z, Z, Z, Z, Z, Z, Z],
    [
        5.26001519587677318785587544488e-2,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
    ],
    [
        1.97250569845378994544595329183e-2,
        5.91751709536136983633785987549e-2,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
    ],
    [
        2.95875854768068491816892993775e-2,
        Z,
        8.87627564304205475450678981324e-2,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
    ],
    [
        2.41365134159266685502369798665e-1,
        Z,
        -8.84549479328286085344864962717e-1,
        9.24834003261792003115737966543e-1,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
    ],
    [
        3.7037037037037037037037037037e-2,
        Z,
        Z,
        1.70828608729473871279604482173e-1,
        1.25467687566822425016691814123e-1,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
    ],
    [
        3.7109375e-2,
        Z,
        Z,
        1.70252211019544039314978060272e-1,
        6.02165389804559606850219397283e-2,
        -1.7578125e-2,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
    ],
    [
        3.70920001185047927108779319836e-2,
        Z,
        Z,
        1.70383925712239993810214054705e-1,
        1.07262030446373284651809199168e-1,
        -1.53194377486244017527936158236e-2,
        8.27378916381402288758473766002e-3,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
    ],
    [
        6.24110958716075717114429577812e-1,
        Z,
        Z,
        -3.36089262944694129406857109825e0,
        -8.68219346841726006818189891453e-1,
        2.75920996994467083049415600797e1,
        2.01540675504778934086186788979e1,
        -4.34898841810699588477366255144e1,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
    ],
    [
        4.77662536438264365890433908527e-1,
        Z,
        Z,
        -2.48811461997166764192642586468e0,
        -5.90290826836842996371446475743e-1,
        2.12300514481811942347288949897e1,
        1.52792336328824235832596922938e1,
        -3.32882109689848629194453265587e1,
        -2.03312017085086261358222928593e-2,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
    ],
    [
        -9.3714243008598732571704021658e-1,
        Z,
        Z,
        5.18637242884406370830023853209e0,
        1.09143734899672957818500254654e0,
        -8.14978701074692612513997267357e0,
        -1.85200656599969598641566180701e1,
        2.27394870993505042818970056734e1,
        2.49360555267965238987089396762e0,
        -3.0467644718982195003823669022e0,
        Z,
        Z,
        Z,
        Z,
        Z,
        Z,
    ],
    [
        2.27331014751653820792359768449e0,
        Z,
        Z,
        -1.05344954667372501984066689879e1,
        -2.00087205822486249909675718444e0,
        -1.79589318631187989172765950534e1,
        2.79488845294199600508499808837e1,
        -2.85899827713502369474065508674e0,
        -8.87285693353062954433549289258e0,
        1.23605671757943030647266201528e1,
        6.43392746015763530355970484046e-1,
        Z,
        Z,
        Z,
        Z,
        Z,
    ],
    [
        B[0], B[1], B[2], B[3], B[4], B[5], B[6], B[7], B[8], B[9], B[10], B[11], Z, Z, Z, Z,
    ],
    [
        5.61675022830479523392909219681e-2,
        Z,
        Z,
        Z,
        Z,
        Z,
        2.53500210216624811088794765333e-1,
        -2.46239037470802489917441475441e-1,
        -1.24191423263816360469010140626e-1,
        1.5329179827876569731206322685e-1,
        8.20105229563468988491666602057e-3,
        7.56789766054569976138603589584e-3,
        -8.298e-3,
        Z,
        Z,
        Z,
    ],
    [
        3.18346481635021405060768473261e-2,
        Z,
        Z,
        Z,
        Z,
        2.83009096723667755288322961402e-2,
        5.35419883074385676223797384372e-2,
        -5.49237485713909884646569340306e-2,
        Z,
        Z,
        -1.08347328697249322858509316994e-4,
        3.82571090835658412954920192323e-4,
        -3.40465008687404560802977114492e-4,
        1.41312443674632500278074618366e-1,
        Z,
        Z,
    ],
    [
        -4.28896301583791923408573538692e-1,
        Z,
        Z,
        Z,
        Z,
        -4.69762141536116384314449447206e0,
        7.68342119606259904184240953878e0,
        4.06898981839711007970213554331e0,
        3.56727187455281109270669543021e-1,
        Z,
        Z,
        Z,
        -1.39902416515901462129418009734e-3,
        2.9475147891527723389556272149e0,
        -9.15095847217987001081870187138e0,
        Z,
    ],
];

/// Coefficients `d_{k,j}` (Hairer's `D4j`..`D7j`, rows `k = 4..=7` here as rows
/// 0..=3) of the dense output: `cont[4 + row] = h * sum_j D[row][j] * k_j`,
/// nonzero at stages 0 and 5..=15.
pub const D: [[f64; 16]; 4] = [
    [
        -0.84289382761090128651353491142e+01,
        Z,
        Z,
        Z,
        Z,
        0.56671495351937776962531783590e+00,
        -0.30689499459498916912797304727e+01,
        0.23846676565120698287728149680e+01,
        0.21170345824450282767155149946e+01,
        -0.87139158377797299206789907490e+00,
        0.22404374302607882758541771650e+01,
        0.63157877876946881815570249290e+00,
        -0.88990336451333310820698117400e-01,
        0.18148505520854727256656404962e+02,
        -0.91946323924783554000451984436e+01,
        -0.44360363875948939664310572000e+01,
    ],
    [
        0.10427508642579134603413151009e+02,
        Z,
        Z,
        Z,
        Z,
        0.24228349177525818288430175319e+03,
        0.16520045171727028198505394887e+03,
        -0.37454675472269020279518312152e+03,
        -0.22113666853125306036270938578e+02,
        0.77334326684722638389603898808e+01,
        -0.30674084731089398182061213626e+02,
        -0.93321305264302278729567221706e+01,
        0.15697238121770843886131091075e+02,
        -0.31139403219565177677282850411e+02,
        -0.93529243588444783865713862664e+01,
        0.35816841486394083752465898540e+02,
    ],
    [
        0.19985053242002433820987653617e+02,
        Z,
        Z,
        Z,
        Z,
        -0.38703730874935176555105901742e+03,
        -0.18917813819516756882830838328e+03,
        0.52780815920542364900561016686e+03,
        -0.11573902539959630126141871134e+02,
        0.68812326946963000169666922661e+01,
        -0.10006050966910838403183860980e+01,
        0.77771377980534432092869265740e+00,
        -0.27782057523535084065932004339e+01,
        -0.60196695231264120758267380846e+02,
        0.84320405506677161018159903784e+02,
        0.11992291136182789328035130030e+02,
    ],
    [
        -0.25693933462703749003312586129e+02,
        Z,
        Z,
        Z,
        Z,
        -0.15418974869023643374053993627e+03,
        -0.23152937917604549567536039109e+03,
        0.35763911791061412378285349910e+03,
        0.93405324183624310003907691704e+02,
        -0.37458323136451633156875139351e+02,
        0.10409964950896230045147246184e+03,
        0.29840293426660503123344363579e+02,
        -0.43533456590011143754432175058e+02,
        0.96324553959188282948394950600e+02,
        -0.39177261675615439165231486172e+02,
        -0.14972683625798562581422125276e+03,
    ],
];

/// The eight rows `cont` of the 7th-order continuous extension of a step of size `h` from `y`
/// to `y_new`, from its sixteen stages `k` (Hairer's `CONT`, `dop853.f`): shared by
/// [`super::Dop853`] and the batched lanes of [`crate::batch`], which must evaluate it
/// bitwise alike.
pub fn dense_rows<const N: usize>(
    y: &[f64; N],
    y_new: &[f64; N],
    h: f64,
    k: &[[f64; N]; 16],
) -> [[f64; N]; 8] {
    let mut cont = [[0.0; N]; 8];
    for i in 0..N {
        let ydiff = y_new[i] - y[i];
        let bspl = h * k[0][i] - ydiff;
        cont[0][i] = y[i];
        cont[1][i] = ydiff;
        cont[2][i] = bspl;
        cont[3][i] = ydiff - h * k[12][i] - bspl;
        for (row, d) in D.iter().enumerate() {
            let mut acc = d[0] * k[0][i];
            for j in 5..16 {
                acc += d[j] * k[j][i];
            }
            cont[4 + row][i] = h * acc;
        }
    }
    cont
}

/// The continuous extension with rows `cont` ([`dense_rows`]) at the fraction `s` of its step
/// (Hairer's `CONTD8`).
pub fn dense_at<const N: usize>(cont: &[[f64; N]; 8], s: f64) -> [f64; N] {
    let s1 = 1.0 - s;
    std::array::from_fn(|i| {
        let conpar = cont[4][i] + s * (cont[5][i] + s1 * (cont[6][i] + s * cont[7][i]));
        cont[0][i] + s * (cont[1][i] + s1 * (cont[2][i] + s * (cont[3][i] + s1 * conpar)))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The coefficients carry ~30 digits but are rounded to f64 (and some were
    /// published with fewer digits), and the large entries (up to ~5e2 in `D`,
    /// ~4e1 in `A`) amplify rounding in the sums: 1e-13 bounds the residuals.
    const TOL: f64 = 1e-13;

    fn dot(a: &[f64], b: &[f64]) -> f64 {
        a.iter().zip(b).map(|(x, y)| x * y).sum()
    }

    #[test]
    fn rows_of_a_sum_to_c() {
        for (i, row) in A.iter().enumerate() {
            let sum: f64 = row.iter().sum();
            assert!((sum - C[i]).abs() < TOL, "row {i}: {sum} vs {}", C[i]);
            assert!(row[i..].iter().all(|&a| a == 0.0), "row {i} not explicit");
        }
    }

    #[test]
    fn weights_sum_to_one_and_estimators_to_zero() {
        assert!((B.iter().sum::<f64>() - 1.0).abs() < TOL);
        // b - BHH is a 3rd-order error estimate: BHH is itself consistent.
        assert!((BHH.iter().sum::<f64>() - 1.0).abs() < TOL);
        // ER = b - b̂ with b̂ of order 5: zero sum.
        assert!(ER.iter().sum::<f64>().abs() < TOL);
    }

    #[test]
    fn quadrature_order_conditions_up_to_8() {
        // sum b_i c_i^k = 1/(k+1), k = 0..=7 (order 8 for quadrature).
        for k in 0..8 {
            let ck: Vec<f64> = C[..12].iter().map(|c| c.powi(k)).collect();
            let lhs = dot(&B, &ck);
            assert!((lhs - 1.0 / (k + 1) as f64).abs() < TOL, "k = {k}: {lhs}");
            // The 5th-order embedded weights b̂ = b - ER satisfy it up to k = 4.
            if k <= 4 {
                assert!(dot(&ER, &ck).abs() < TOL, "ER, k = {k}");
            }
        }
    }

    #[test]
    fn tree_order_conditions() {
        // sum b_i a_ij c_j^k = 1/((k+1)(k+2)) for k = 0..=6 (trees [τ^k]),
        // and sum b_i c_i a_ij c_j^k = 1/((k+1)(k+3)) for k = 0..=5.
        for k in 0..7 {
            let ack: Vec<f64> = (0..12)
                .map(|i| (0..12).map(|j| A[i][j] * C[j].powi(k)).sum())
                .collect();
            let lhs = dot(&B, &ack);
            let rhs = 1.0 / ((k + 1) * (k + 2)) as f64;
            assert!((lhs - rhs).abs() < TOL, "k = {k}: {lhs} vs {rhs}");
            if k < 6 {
                let bc: Vec<f64> = (0..12).map(|i| B[i] * C[i]).collect();
                let lhs = dot(&bc, &ack);
                let rhs = 1.0 / ((k + 1) * (k + 3)) as f64;
                assert!((lhs - rhs).abs() < TOL, "k = {k}: {lhs} vs {rhs}");
            }
        }
    }

    #[test]
    fn dense_output_reproduces_the_step() {
        // The CONTD8 form matches y_old, y_new and h f at both step ends by
        // construction; the D rows add the higher-order corrections, which
        // must vanish for y' = 1 (all stages equal): each row of D sums to
        // zero. Entries reach 5e2, so the rounding bound is 1e-11.
        for (r, row) in D.iter().enumerate() {
            let sum: f64 = row.iter().sum();
            assert!(sum.abs() < 1e-11, "row {r} of D sums to {sum}");
        }
    }
}
