//! The implicit-expression parser on arbitrary text, then the parsed surface evaluated,
//! projected onto and (for short inputs) traced as a tiny net: errors, never a panic or a hang.
#![no_main]

use karkas::implicit::{
    project_onto, trace_net, ExpressionSurface, ImplicitSurface, NetDirections, NetSpec,
};
use karkas::Point;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let split = data.iter().position(|&b| b == 0).unwrap_or(data.len());
    let (text, rest) = data.split_at(split);
    let Ok(text) = std::str::from_utf8(text) else {
        return;
    };
    let Ok(surface) = ExpressionSurface::parse(text) else {
        return;
    };
    let mut input = karkas_fuzz::Input::new(rest);
    let p: Point<3> = input.point();
    let _ = surface.value(p);
    let _ = surface.gradient(p);
    let _ = surface.hessian(p);
    if let Ok(q) = project_onto(&surface, p) {
        assert!(q.is_finite());
    }
    if input.byte() % 8 == 0 {
        let nodes = (input.count(2, 3), input.count(2, 3));
        let step = f64::from(input.byte()) / 64.0;
        let directions = if input.flag() {
            NetDirections::Principal
        } else {
            NetDirections::Turned {
                angle: input.float(),
            }
        };
        let mut spec = NetSpec::new(p, directions, nodes, (step, step));
        // Closed lines that never close are traced for up to 200000 steps before the error:
        // correct, but too slow for fuzzing.
        spec.closed_v = false;
        spec.substeps = 4;
        if let Ok(g) = trace_net(&surface, &spec) {
            assert!(g.as_slice().iter().all(|q| q.is_finite()));
        }
    }
});
