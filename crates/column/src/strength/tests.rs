use super::*;

/// The stack path of the per-cell C entry gives the per-column routine's bits and errors
/// for every option pair, with and without aice0, on ordinary and edge columns.
#[test]
fn constant_cf_path_is_bit_identical_to_the_column_routine() {
    let mut state: u64 = 987654321;
    let mut rnd = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    for ncat in [1, 5, 16] {
        let mut ws = Workspace::new(ncat);
        for part in [Participation::Thorndike, Participation::Exponential] {
            for redist in [Redistribution::Uniform, Redistribution::Exponential] {
                let opts = StrengthOptions {
                    participation: part,
                    redistribution: redist,
                    ..StrengthOptions::default()
                };
                let k = StrengthConsts::new(&opts).unwrap();
                // Fewer columns under Miri (scripts/check-ub.sh), which interprets every operation.
                for c in 0..if cfg!(miri) { 27 } else { 3000 } {
                    let kind = c % 9;
                    let mut w: Vec<f64> = (0..=ncat).map(|_| rnd()).collect();
                    match kind {
                        1 => w[ncat / 2 + 1] = 0.0,
                        2 => w[0] = 1e-13,
                        3 => w[1..].iter_mut().for_each(|x| *x = 0.0),
                        4 => w.iter_mut().for_each(|x| *x = 0.0),
                        _ => {}
                    }
                    let s: f64 = w.iter().sum::<f64>().max(1e-300);
                    let mut a: Vec<f64> = w[1..].iter().map(|x| x / s).collect();
                    let mut v: Vec<f64> = a.iter().map(|x| x * (0.01 + 6.0 * rnd())).collect();
                    let mut a0 = w[0] / s;
                    match kind {
                        5 => a[0] = f64::NAN,
                        6 => v[ncat - 1] = -1.0,
                        7 => a0 += 0.1,
                        8 => v[0] = 1e300,
                        _ => {}
                    }
                    for given in [Some(a0), None] {
                        let want = strength_column(&a, &v, given, &opts, &mut ws);
                        let got = strength_column_constant_cf(&a, &v, given, &opts, &k);
                        match (want, got) {
                            (Ok(x), Ok(y)) => assert_eq!(
                                x.strength.to_bits(),
                                y.strength.to_bits(),
                                "{part:?}/{redist:?} ncat {ncat} column {c}"
                            ),
                            (Err(x), Err(y)) => assert_eq!(x.to_string(), y.to_string()),
                            (x, y) => panic!("column {c}: {x:?} vs {y:?}"),
                        }
                    }
                }
            }
        }
    }
}
