//! Reference cycles among the kept instances of a STEP file, refused before any geometry is
//! built.
//!
//! The resolvers guard each chain of references they follow, but instances that only refer
//! to each other (two TRIMMED_CURVEs trimming each other's basis) are never reached from an
//! item nothing refers to, and would be left out without a word. One depth-first walk over
//! every kept instance (ids ascending, so the error names the same instance every time)
//! finds any reference back to an instance still on the walk's path: `O(instances +
//! references)` time, one state byte and the path's stack of references as memory.

use std::collections::HashMap;
use std::path::Path;

use super::step_syntax::{Exchange, Value};
use crate::error::{IoError, Location};

/// Where an instance is in the walk.
#[derive(Clone, Copy, PartialEq, Eq)]
enum State {
    /// On the current path (its references being walked).
    Open,
    /// Walked completely: no cycle through it.
    Done,
}

/// Refuses a cycle of references among `exchange`'s instances, naming the instance (line,
/// `#n` and type) whose reference closes it.
pub(crate) fn refuse_cycles(path: &Path, exchange: &Exchange) -> Result<(), IoError> {
    let mut ids: Vec<u64> = exchange.instances.keys().copied().collect();
    ids.sort_unstable();
    let mut state: HashMap<u64, State> = HashMap::with_capacity(ids.len());
    // The path: each instance with its references and the next one to follow.
    let mut stack: Vec<(u64, Vec<u64>, usize)> = Vec::new();
    for root in ids {
        if state.contains_key(&root) {
            continue;
        }
        state.insert(root, State::Open);
        stack.push((root, references(exchange, root), 0));
        while let Some((id, refs, next)) = stack.last_mut() {
            let Some(&r) = refs.get(*next) else {
                state.insert(*id, State::Done);
                stack.pop();
                continue;
            };
            *next += 1;
            if !exchange.instances.contains_key(&r) {
                continue;
            }
            match state.get(&r) {
                Some(State::Done) => {}
                Some(State::Open) => {
                    let id = *id;
                    let instance = &exchange.instances[&id];
                    return Err(Location::new(path, instance.line).error(format!(
                        "#{id} ({}): refers to #{r}, which refers back to #{id} (a cycle of \
                         references)",
                        instance.kind(&[])
                    )));
                }
                None => {
                    state.insert(r, State::Open);
                    let refs = references(exchange, r);
                    stack.push((r, refs, 0));
                }
            }
        }
    }
    Ok(())
}

/// The references of instance `id`, in the order its parameters give them.
fn references(exchange: &Exchange, id: u64) -> Vec<u64> {
    let mut out = Vec::new();
    if let Some(instance) = exchange.instances.get(&id) {
        for part in &instance.parts {
            push_refs(&part.params, &mut out);
        }
    }
    out
}

/// Appends every reference in `values` (lists and typed values searched) to `out`.
pub(crate) fn push_refs(values: &[Value], out: &mut Vec<u64>) {
    for v in values {
        match v {
            Value::Ref(r) => out.push(*r),
            Value::List(l) => push_refs(l, out),
            Value::Typed(_, inner) => push_refs(std::slice::from_ref(inner), out),
            _ => {}
        }
    }
}
