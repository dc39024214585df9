//! Blending families of Chashnikov (docs/methods.md §2): the duality `L_i(H_j) = delta_ij` for every
//! family, the cubic-spline cardinal functions against SciPy, derivatives against differences,
//! periodicity, partition of unity where it must hold, locality of the piecewise Hermite family.

use karkas::coons::{
    BlendingFamily, CubicHermiteBlending, Functional, LagrangeBlending, LlBlending,
    PiecewiseHermiteBlending, SplineBlending, SplineEnds,
};

/// Every family of the crate on a few node sets (even and uneven, few and many nodes).
fn families() -> Vec<(String, Box<dyn BlendingFamily>)> {
    let uneven = [0.0, 0.7, 1.5, 2.0, 3.1, 4.0];
    let many: Vec<f64> = (0..15).map(|i| i as f64 + 0.3 * (i as f64).sin()).collect();
    let mut out: Vec<(String, Box<dyn BlendingFamily>)> = vec![
        (
            "hermite".into(),
            Box::new(CubicHermiteBlending::new(-1.0, 2.5).unwrap()),
        ),
        (
            "lagrange 2".into(),
            Box::new(LagrangeBlending::new(&[0.0, 1.0]).unwrap()),
        ),
        (
            "lagrange uneven".into(),
            Box::new(LagrangeBlending::new(&uneven).unwrap()),
        ),
        (
            "piecewise hermite".into(),
            Box::new(PiecewiseHermiteBlending::new(&uneven).unwrap()),
        ),
        (
            "piecewise hermite 2".into(),
            Box::new(PiecewiseHermiteBlending::new(&[3.0, 5.0]).unwrap()),
        ),
        (
            "ll open".into(),
            Box::new(LlBlending::new(0.0, 2.0, 7, 3, false).unwrap()),
        ),
        (
            "ll closed".into(),
            Box::new(LlBlending::new(1.0, 3.0, 6, 2, true).unwrap()),
        ),
    ];
    for ends in [
        SplineEnds::Natural,
        SplineEnds::NotAKnot,
        SplineEnds::Periodic,
    ] {
        for nodes in [
            &uneven[..],
            &many[..],
            &uneven[..4],
            &uneven[..3],
            &uneven[..2],
        ] {
            if ends == SplineEnds::Periodic && nodes.len() < 4 {
                continue;
            }
            out.push((
                format!("spline {ends:?} {}", nodes.len()),
                Box::new(SplineBlending::new(nodes, ends).unwrap()),
            ));
        }
    }
    out
}

/// `L(H_j)` for every `j`.
fn apply(l: &Functional, family: &dyn BlendingFamily) -> Vec<f64> {
    let mut w = vec![0.0; family.len()];
    family.eval_into(l.at(), l.order(), &mut w);
    w
}

#[test]
fn every_family_is_dual_to_its_functionals() {
    for (name, family) in families() {
        let m = family.len();
        assert_eq!(family.functionals().len(), m, "{name}");
        for (i, l) in family.functionals().iter().enumerate() {
            let row = apply(l, family.as_ref());
            for (j, &x) in row.iter().enumerate() {
                let expected = if i == j { 1.0 } else { 0.0 };
                assert!(
                    (x - expected).abs() < 1e-11,
                    "{name}: L_{i}(H_{j}) = {x}, expected {expected}"
                );
            }
        }
    }
}

#[test]
fn derivatives_match_central_differences() {
    for (name, family) in families() {
        let d = family.domain();
        let m = family.len();
        let (mut lo, mut hi, mut dw) = (vec![0.0; m], vec![0.0; m], vec![0.0; m]);
        for k in 0..3 {
            for s in [0.13, 0.41, 0.77, 0.93] {
                let t = d.start + s * d.length();
                let e = 1e-6 * d.length();
                family.eval_into(t - e, k, &mut lo);
                family.eval_into(t + e, k, &mut hi);
                family.eval_into(t, k + 1, &mut dw);
                for j in 0..m {
                    let fd = (hi[j] - lo[j]) / (2.0 * e);
                    let scale = 1.0 + dw[j].abs();
                    assert!(
                        (fd - dw[j]).abs() < 2e-4 * scale,
                        "{name}: H_{j}^({}) at {t}: {} vs difference {fd}",
                        k + 1,
                        dw[j]
                    );
                }
            }
        }
    }
}

#[test]
fn value_interpolating_families_are_a_partition_of_unity() {
    // Families whose functionals are all values reproduce constants: sum_j H_j = 1.
    for (name, family) in families() {
        if family.functionals().iter().any(|l| l.order() != 0) {
            continue;
        }
        let d = family.domain();
        let mut w = vec![0.0; family.len()];
        for k in 0..=20 {
            family.eval_into(d.uniform(k, 21), 0, &mut w);
            let sum: f64 = w.iter().sum();
            assert!((sum - 1.0).abs() < 1e-12, "{name}: sum {sum}");
        }
    }
}

// Reference values from SciPy 1.17:
// python3 -c "import numpy as np; from scipy.interpolate import CubicSpline;
//   x=np.array([0,0.7,1.5,2.0,3.1,4.0]); t=np.array([0.3,1.2,2.5,3.9]);
//   print(CubicSpline(x, np.eye(6), bc_type=BC)(t, K).round(15).tolist())"
// with BC in 'natural', 'not-a-knot' and K in 0, 1, 2; periodic:
//   CubicSpline(x, np.vstack([np.eye(5), np.eye(5)[0]]), bc_type='periodic')(t, K).
const NATURAL: [[[f64; 6]; 4]; 3] = [
    [
        [
            0.482225462536623,
            0.620667815938394,
            -0.14949665184711,
            0.050578174432326,
            -0.00502262443341,
            0.001047823373177,
        ],
        [
            -0.066956583319462,
            0.397979257740974,
            0.861398285165608,
            -0.208832540527221,
            0.020737945414507,
            -0.004326364474406,
        ],
        [
            -0.009820096737046,
            0.050634873800391,
            -0.338461909163196,
            0.886549406059802,
            0.494712515772532,
            -0.083614789732483,
        ],
        [
            0.000698548915451,
            -0.003601892845295,
            0.02407636155717,
            -0.051520349498455,
            0.168824273146283,
            0.861523058724846,
        ],
    ],
    [
        [
            -1.59211046154,
            1.780748138744198,
            -0.274077195053035,
            0.092726653125931,
            -0.009208144794584,
            0.001921009517491,
        ],
        [
            0.21789204251972,
            -1.650849594242306,
            1.418515360495296,
            0.015673965514184,
            -0.001556490384312,
            0.000324716097417,
        ],
        [
            0.006663637071567,
            -0.034359378650265,
            0.229670581217883,
            -1.302885798267852,
            1.242585049722896,
            -0.141674091094228,
        ],
        [
            -0.006810851925649,
            0.035118455241629,
            -0.234744525182411,
            0.502323407609938,
            -1.673814440954034,
            1.377927955210526,
        ],
    ],
    [
        [
            1.338046633379223,
            -2.881445810504477,
            2.242449777706652,
            -0.75867261648489,
            0.075339366501143,
            -0.015717350597652,
        ],
        [
            0.549776849342765,
            0.680838120576369,
            -4.441878666339935,
            3.485152331977463,
            -0.346090214864626,
            0.072201579307965,
        ],
        [
            0.072091980014025,
            -0.371724271947315,
            2.484740206158383,
            -2.612294521398614,
            -0.054376994698539,
            0.481563601872062,
        ],
        [
            -0.005239116865884,
            0.027014196339715,
            -0.180572711678778,
            0.386402621238414,
            -0.432848715263787,
            0.20524372623032,
        ],
    ],
];
const NOT_A_KNOT: [[[f64; 6]; 4]; 3] = [
    [
        [
            0.37748758478097,
            0.886678518289502,
            -0.439467063438388,
            0.188421971643938,
            -0.015739704634605,
            0.002618693358582,
        ],
        [
            -0.043288052404784,
            0.338080423566694,
            0.924333829297985,
            -0.235527464554923,
            0.019674630793257,
            -0.003273366698228,
        ],
        [
            -0.0074201464706,
            0.048912098316941,
            -0.384789665900176,
            0.974447573257258,
            0.423721866302686,
            -0.054871725506109,
        ],
        [
            0.002506360585625,
            -0.016521419875944,
            0.129973398259615,
            -0.227328554037603,
            0.304687617415874,
            0.806682597652434,
        ],
    ],
    [
        [
            -1.523809523809524,
            1.607142857142857,
            -0.083333333333333,
            0.0,
            0.0,
            0.0,
        ],
        [
            0.140691645250011,
            -1.454754497497633,
            1.204499752017674,
            0.117763732277461,
            -0.009837315396628,
            0.001636683349114,
        ],
        [
            0.002473382156867,
            -0.016304032772314,
            0.128263221966725,
            -1.142997675934237,
            1.121385640525367,
            -0.092820535942408,
        ],
        [
            -0.020611517973888,
            0.13586693976928,
            -1.068860183056043,
            1.888616996421676,
            -2.745553738384795,
            1.81054150322377,
        ],
    ],
    [
        [
            3.342982100184862,
            -7.973758961179498,
            7.795933089859779,
            -3.402063376904444,
            0.28418911145815,
            -0.04728196341885,
        ],
        [
            0.355909386614107,
            1.16954261753396,
            -4.934081789079761,
            3.663760559743246,
            -0.306049812339546,
            0.050919037527992,
        ],
        [
            0.052765486013153,
            -0.347819365809356,
            2.736282068623473,
            -3.111223147203128,
            0.3538700955176,
            0.316124862858259,
        ],
        [
            -0.085743914771373,
            0.565206469440204,
            -4.446458361513142,
            7.442101250568719,
            -5.878069208246406,
            2.402963764521995,
        ],
    ],
];
const PERIODIC: [[[f64; 5]; 4]; 3] = [
    [
        [
            0.647984367478117,
            0.50756627919496,
            -0.130442579069103,
            0.066953166898592,
            -0.092061234502566,
        ],
        [
            -0.112331197714669,
            0.426165704593644,
            0.856649750131088,
            -0.212913412177182,
            0.042429155167119,
        ],
        [
            -0.175433793343027,
            0.10694075371065,
            -0.347947689502976,
            0.87839736510718,
            0.538043364028174,
        ],
        [
            1.008367517632107,
            -0.103955353289215,
            0.040982782052243,
            -0.036991040648651,
            0.091596094253515,
        ],
    ],
    [
        [
            -1.695162571729316,
            1.852829634673589,
            -0.286220673461307,
            0.082290597288083,
            0.046263013228952,
        ],
        [
            0.339203439546942,
            -1.733927061819816,
            1.432511316332973,
            0.02770203290273,
            -0.06548972696283,
        ],
        [
            -0.261039515392157,
            0.052180521273288,
            0.215091313784184,
            -1.31541516126399,
            1.309182841598676,
        ],
        [
            0.217490104808322,
            0.827275152374939,
            -0.368198161564061,
            0.387633896563901,
            -1.064200992183101,
        ],
    ],
    [
        [
            -1.82657600060217,
            -0.719198903865712,
            1.878178777423286,
            -1.071725629077768,
            1.739321756122364,
        ],
        [
            0.99260661150034,
            0.426340265049079,
            -4.399003734657406,
            3.52199887347401,
            -0.541942015366022,
        ],
        [
            1.034517566101639,
            -0.701915955824505,
            2.540367181321071,
            -2.564488925722423,
            -0.308479865875781,
        ],
        [
            -5.643763134587005,
            4.039732138079902,
            -0.856590225684598,
            -0.194564074327367,
            2.655185296519072,
        ],
    ],
];

fn check_against(family: &SplineBlending, expected: &[Vec<Vec<f64>>], what: &str) {
    let ts = [0.3, 1.2, 2.5, 3.9];
    let mut w = vec![0.0; family.len()];
    for (k, rows) in expected.iter().enumerate() {
        for (t, row) in ts.iter().zip(rows) {
            family.eval_into(*t, k, &mut w);
            for (j, (a, b)) in w.iter().zip(row).enumerate() {
                assert!(
                    (a - b).abs() < 1e-12,
                    "{what}: C_{j}^({k})({t}) = {a}, SciPy {b}"
                );
            }
        }
    }
}

fn nested<const N: usize>(table: &[[[f64; N]; 4]; 3]) -> Vec<Vec<Vec<f64>>> {
    table
        .iter()
        .map(|k| k.iter().map(|r| r.to_vec()).collect())
        .collect()
}

#[test]
fn spline_cardinal_functions_match_scipy() {
    let x = [0.0, 0.7, 1.5, 2.0, 3.1, 4.0];
    let natural = SplineBlending::new(&x, SplineEnds::Natural).unwrap();
    check_against(&natural, &nested(&NATURAL), "natural");
    let not_a_knot = SplineBlending::new(&x, SplineEnds::NotAKnot).unwrap();
    check_against(&not_a_knot, &nested(&NOT_A_KNOT), "not-a-knot");
    let periodic = SplineBlending::new(&x, SplineEnds::Periodic).unwrap();
    assert_eq!(periodic.len(), 5);
    check_against(&periodic, &nested(&PERIODIC), "periodic");
}

#[test]
fn periodic_families_repeat_with_their_period() {
    for (name, family) in families() {
        if !family.is_periodic() {
            continue;
        }
        let d = family.domain();
        let m = family.len();
        let (mut a, mut b) = (vec![0.0; m], vec![0.0; m]);
        for k in 0..3 {
            for s in [0.0, 0.2, 0.55, 0.999] {
                let t = d.start + s * d.length();
                family.eval_into(t, k, &mut a);
                family.eval_into(t + d.length(), k, &mut b);
                for j in 0..m {
                    assert!((a[j] - b[j]).abs() < 1e-9, "{name}: H_{j}^({k}) at {t}");
                }
            }
        }
        // C^2 across the seam: the second derivative just below the end equals the one at
        // the start.
        family.eval_into(d.end - 1e-9 * d.length(), 2, &mut a);
        family.eval_into(d.start, 2, &mut b);
        for j in 0..m {
            assert!(
                (a[j] - b[j]).abs() < 1e-5 * (1.0 + b[j].abs()),
                "{name}: seam"
            );
        }
    }
}

#[test]
fn piecewise_hermite_is_local_and_matches_the_seed() {
    // Formula (17) with integer nodes: H_{2i}(u) = H_1(u - i) on [i, i+1], H_4(u - i + 1) on
    // [i-1, i]; H_{2i+1}(u) = H_2(u - i), H_3(u - i + 1).
    let nodes = [0.0, 1.0, 2.0, 3.0];
    let family = PiecewiseHermiteBlending::new(&nodes).unwrap();
    let mut w = [0.0; 8];
    for &u in &[0.25, 1.5, 2.75] {
        let range = family.eval_into(u, 0, &mut w);
        let i = u as usize;
        assert_eq!(range, 2 * i..2 * i + 4);
        let x = u - i as f64;
        let h = |k: usize| karkas::coons::hermite_cubic(x, 0)[k - 1];
        assert!((w[2 * i] - h(1)).abs() < 1e-15);
        assert!((w[2 * i + 1] - h(2)).abs() < 1e-15);
        assert!((w[2 * i + 2] - h(4)).abs() < 1e-15);
        assert!((w[2 * i + 3] - h(3)).abs() < 1e-15);
        for (j, &x) in w.iter().enumerate() {
            if !range.contains(&j) {
                assert_eq!(x, 0.0);
            }
        }
    }
}

#[test]
fn lagrange_oscillates_where_splines_do_not() {
    // Runge's phenomenon: on 15 even nodes the middle-node Lagrange function swings far
    // outside [0, 1] near the ends; the cubic-spline cardinal function stays small there.
    let nodes: Vec<f64> = (0..15).map(|i| i as f64).collect();
    let lagrange = LagrangeBlending::new(&nodes).unwrap();
    let spline = SplineBlending::new(&nodes, SplineEnds::NotAKnot).unwrap();
    let swing = |f: &dyn BlendingFamily| {
        let mut w = vec![0.0; 15];
        (0..=280)
            .map(|k| {
                f.eval_into(k as f64 * 0.05, 0, &mut w);
                w.iter().fold(0.0f64, |m, x| m.max(x.abs()))
            })
            .fold(0.0, f64::max)
    };
    let (l, s) = (swing(&lagrange), swing(&spline));
    assert!(l > 10.0, "Lagrange max |H_j| = {l}");
    assert!(s < 1.5, "spline max |C_j| = {s}");
}

#[test]
fn bad_nodes_are_errors() {
    assert!(LagrangeBlending::new(&[0.0]).is_err());
    assert!(LagrangeBlending::new(&[0.0, 0.0]).is_err());
    assert!(SplineBlending::new(&[0.0, f64::NAN, 1.0], SplineEnds::Natural).is_err());
    assert!(SplineBlending::new(&[0.0, 1.0, 2.0], SplineEnds::Periodic).is_err());
    assert!(PiecewiseHermiteBlending::new(&[1.0, 0.5]).is_err());
    assert!(CubicHermiteBlending::new(1.0, 1.0).is_err());
    assert!(LlBlending::new(0.0, 1.0, 2, 3, false).is_err());
    assert!(LlBlending::new(0.0, 1.0, 5, 0, false).is_err());
    assert!(LlBlending::new(1.0, 0.0, 5, 3, false).is_err());
}

#[test]
fn nan_parameters_never_panic() {
    for (_, family) in families() {
        let mut w = vec![0.0; family.len()];
        for k in 0..4 {
            family.eval_into(f64::NAN, k, &mut w);
            family.eval_into(f64::INFINITY, k, &mut w);
            family.eval_into(-1e300, k, &mut w);
        }
    }
}

// The spline curves of point networks against SciPy 1.17:
// python3 -c "import numpy as np; from scipy.interpolate import CubicSpline;
//   x=np.array([0,0.7,1.5,2.0,3.1,4.0]); t=np.array([0.3,1.2,2.5,3.9]);
//   y=np.stack([np.sin(1.3*x), x**2, np.cos(x)], axis=1);
//   print(CubicSpline(x, y, bc_type=BC)(t, K).round(14).tolist())"
// (periodic: y[-1] = y[0]; three points: CubicSpline(x[:3], y[:3])([0.3, 1.2])).
const CURVE_NOT_A_KNOT: [[[f64; 3]; 4]; 4] = [
    [
        [0.39882218235585, 0.09, 0.96017324434585],
        [0.99179293151889, 1.44, 0.36117091608672],
        [-0.09686919161804, 6.25, -0.79023118661723],
        [-0.95861775934922, 15.21, -0.73804094765604],
    ],
    [
        [1.19143198634662, 0.6, -0.30049363247938],
        [0.03729348916945, 2.4, -0.92701102939153],
        [-1.27120674209357, 5.0, -0.5850130407674],
        [0.61913003479986, 7.8, 0.78148542567886],
    ],
    [
        [-0.98575177330197, 2.0, -1.04150251817808],
        [-1.5790004426473, 2.0, -0.35075836384891],
        [0.10954196525372, 2.0, 0.7148241174305],
        [2.59093914459403, 2.00000000000001, 1.23731654892131],
    ],
    [
        [-0.65916518816148, 0.0, 0.76749350481019],
        [-0.65916518816149, 0.0, 0.76749350481019],
        [1.77242655667164, 0.0, 0.37320887963629],
        [1.77242655667164, 0.0, 0.37320887963629],
    ],
];
const CURVE_NATURAL: [[[f64; 3]; 4]; 2] = [
    [
        [0.38018850830294, 0.13857021404888, 0.92964884791171],
        [0.99448504090722, 1.42789563964973, 0.36738053831962],
        [-0.12748446066946, 6.22582005763851, -0.8035993780765],
        [-0.89917227721729, 15.25309569254894, -0.71072052286442],
    ],
    [
        [1.20455038359418, 0.56904539242295, -0.2801499917647],
        [0.02339271835946, 2.43567670695786, -0.9495853404107],
        [-1.32457982202995, 4.96283638945958, -0.61008384219375],
        [0.15026385602399, 7.45981699764787, 0.56609678143593],
    ],
];
const CURVE_PERIODIC: [[[f64; 3]; 4]; 2] = [
    [
        [0.38550983212264, -0.66168412207524, 1.09108459439518],
        [0.98956744571735, 1.69237366549312, 0.3204261006781],
        [-0.20354262820233, 7.953704856676, -1.02137416133983],
        [-0.13415554648194, 0.77354743968751, 0.85563391231148],
    ],
    [
        [1.20344610684369, 1.03763995198467, -0.37875472519376],
        [0.02690834331326, 1.85497805695561, -0.83174031030041],
        [-1.45310577564158, 7.82911037414564, -0.96655943079746],
        [1.33681405645356, -9.09951698747941, 1.72614773268097],
    ],
];

#[test]
fn spline_curves_match_scipy() {
    use karkas::param::CubicSpline;
    use karkas::{Curve, Point3};
    let x = [0.0, 0.7, 1.5, 2.0, 3.1, 4.0];
    let ts = [0.3, 1.2, 2.5, 3.9];
    let mut pts: Vec<Point3> = x
        .iter()
        .map(|&t: &f64| Point3::new([(1.3 * t).sin(), t * t, t.cos()]))
        .collect();
    let check = |curve: &CubicSpline<3>, table: &[[[f64; 3]; 4]], what: &str| {
        for (k, rows) in table.iter().enumerate() {
            for (t, row) in ts.iter().zip(rows) {
                let got = curve.deriv(*t, k);
                let tol = 1e-12 * (1.0 + Point3::new(*row).norm());
                assert!(
                    got.distance(Point3::new(*row)) < tol,
                    "{what}: derivative {k} at {t}: {got:?} vs SciPy {row:?}"
                );
            }
        }
    };
    let nak = CubicSpline::new(&x, &pts, SplineEnds::NotAKnot).unwrap();
    check(&nak, &CURVE_NOT_A_KNOT, "not-a-knot");
    let natural = CubicSpline::new(&x, &pts, SplineEnds::Natural).unwrap();
    check(&natural, &CURVE_NATURAL, "natural");
    let three = CubicSpline::new(&x[..3], &pts[..3], SplineEnds::NotAKnot).unwrap();
    assert!(
        three
            .eval(0.3)
            .distance(Point3::new([0.41464214687172, 0.09, 0.9417534002304]))
            < 1e-12
    );
    assert!(
        three
            .eval(1.2)
            .distance(Point3::new([0.97201797587405, 1.44, 0.38419572123102]))
            < 1e-12
    );
    pts[5] = pts[0];
    let periodic = CubicSpline::new(&x, &pts, SplineEnds::Periodic).unwrap();
    check(&periodic, &CURVE_PERIODIC, "periodic");
    assert!(periodic.is_closed());
    assert!(periodic.eval(0.3 + 4.0).distance(periodic.eval(0.3)) < 1e-12);
    // A periodic curve must repeat its first point.
    pts[5][0] += 0.1;
    assert!(CubicSpline::new(&x, &pts, SplineEnds::Periodic).is_err());
    assert!(CubicSpline::new(&x[..3], &pts[..2], SplineEnds::Natural).is_err());
}
