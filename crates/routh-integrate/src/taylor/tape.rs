//! An expression tape of a vector field, recorded once through the [`Scalar`] trait, and the
//! recurrences that give the Taylor coefficients of every intermediate quantity from it.
//!
//! Recording: the field, written once generic over [`Scalar`] (e.g. (m-eq)/(mg-eq) in
//! [`crate::field`]), is called with [`Var`]s. Each arithmetic operation on them appends a node
//! to a thread-local recorder, with three simplifications made at record time:
//! * constant folding: an operation on constants is a constant (the body's parameters, such as
//!   `m R` or `2 R m G`, are folded into single numbers), with the same `f64` operation;
//! * exact identities only: `x + 0 = x`, `x * 1 = x`, `x * (-1) = -x`, `x / 1 = x`, `x * 0 = 0`
//!   (the last one changes at most the sign of a zero, or drops a NaN of a non-finite `x`, which
//!   the integrator refuses anyway);
//! * common-subexpression elimination: an operation already on the tape with the same operands
//!   is not recorded twice (sums and products with their operands in a canonical order, which
//!   IEEE arithmetic allows: `a + b` and `a * b` are commutative bit for bit).
//!
//! Compilation: the nodes that the outputs depend on are laid out in slots
//! `[inputs y_1..y_N, time, constants, operations]` and the operations become a flat array of
//! `Instr` (a `match` on a small enum per operation and order: no dynamic dispatch, no
//! allocation). Every slot owns `stride` contiguous Taylor coefficients
//! `x^[0], x^[1], ...` (normalised derivatives `x^(k) / k!`) between a few places on either
//! side, so the convolutions below read two contiguous runs, one forward and one backward, in
//! a single array.
//!
//! Recurrences for `w^[k]` (order `k`, given all orders below `k`; R. E. Moore, *Interval
//! Analysis* (1966), ch. 11; A. Jorba, M. Zou, Experimental Math. 14 (2005) 99–117, sect. 2):
//! * `w = a ± b`: `a^[k] ± b^[k]`; `w = c a`: `c a^[k]`;
//! * `w = a b`: `sum_{j=0..k} a^[j] b^[k-j]`;
//! * `w = a / b`: `(a^[k] - sum_{j=1..k} b^[j] w^[k-j]) (1 / b^[0])` (a product by the
//!   reciprocal: `recurrence::quotient`);
//! * `w = sqrt(a)`: `(a^[k] - sum_{j=1..k-1} w^[j] w^[k-j]) / (2 w^[0])`;
//! * `w = a b + c` (fused): the product's sum plus `c^[k]`.
//!
//! The pass of order `k` first sums, for every product, quotient and square root, the terms
//! that use only orders `1 .. k-1` (its history, `taylor::convolution`: independent sums, in
//! groups that share their loads for the model families, `taylor::codegen`), then runs
//! through the tape adding the end terms, which need the order
//! `k` just computed by the operations before (`taylor::recurrence`); for the tapes of the model
//! families this run is generated straight-line code (`taylor::codegen`), in the
//! interpreter's arithmetic.
//!
//! At order 0 every recurrence is the `f64` operation itself, so the tape reproduces the `f64`
//! field bit for bit. Cost of all orders `0..p`: `O(p)` for each linear operation and
//! `O(p^2)` for each product, quotient and square root: `O(n_ops p^2)` per step.

use std::cell::RefCell;
use std::collections::HashMap;
use std::fmt::Write as _;
use std::ops::{Add, Div, Mul, Neg, Sub};

use super::coefficient::Coefficient;
use super::convolution::{self, History};
use super::kernels::{Interpreted, Kernels};
use super::recurrence;
use crate::scalar::Scalar;
use crate::OdeSystem;
use std::marker::PhantomData;

/// A recorded operation; constants as their bits (so that nodes can be hashed for
/// common-subexpression elimination).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
enum Node {
    /// State component `i`.
    Input(u32),
    /// The independent variable.
    Time,
    /// A constant that an operation needs as a series (`[c, 0, 0, ...]`).
    Const(u64),
    Add(u32, u32),
    Sub(u32, u32),
    Mul(u32, u32),
    Div(u32, u32),
    Neg(u32),
    Sqrt(u32),
    MulAdd(u32, u32, u32),
    /// `a + c`.
    AddC(u32, u64),
    /// `c - a`.
    CSub(u64, u32),
    /// `a * c`.
    MulC(u32, u64),
    /// `a / c`.
    DivC(u32, u64),
    /// `c / a`.
    CDiv(u64, u32),
}

/// The nodes recorded so far and the index of each (for common-subexpression elimination).
#[derive(Default)]
struct Recorder {
    nodes: Vec<Node>,
    index: HashMap<Node, u32>,
}

impl Recorder {
    fn push(&mut self, node: Node) -> u32 {
        if let Some(&i) = self.index.get(&node) {
            return i;
        }
        let i = self.nodes.len() as u32;
        self.nodes.push(node);
        self.index.insert(node, i);
        i
    }
}

thread_local! {
    /// The recorders of the recordings under way on this thread (innermost last).
    static RECORDERS: RefCell<Vec<Recorder>> = const { RefCell::new(Vec::new()) };
}

fn record(node: Node) -> Var {
    RECORDERS.with(|r| {
        let mut stack = r.borrow_mut();
        let recorder = stack
            .last_mut()
            .expect("a taylor::Var node is only used inside Tape::record");
        Var(Value::Node(recorder.push(node)))
    })
}

/// A number on the tape: a constant, or a node recorded by [`Tape::record`].
///
/// Implements [`Scalar`], so that the generic field can be called with it; its operations
/// record themselves (folding constants). Obtained only inside [`OdeSystem::record`].
#[derive(Debug, Clone, Copy)]
pub struct Var(Value);

#[derive(Debug, Clone, Copy)]
enum Value {
    Const(f64),
    Node(u32),
}

impl Var {
    fn node(self) -> Option<u32> {
        match self.0 {
            Value::Node(i) => Some(i),
            Value::Const(_) => None,
        }
    }

    /// The node of `self`, recording a constant as a [`Node::Const`].
    fn as_node(self) -> u32 {
        match self.0 {
            Value::Node(i) => i,
            Value::Const(c) => record(Node::Const(c.to_bits())).node().expect("a node"),
        }
    }
}

fn constant(c: f64) -> Var {
    Var(Value::Const(c))
}

impl Add for Var {
    type Output = Var;
    fn add(self, other: Var) -> Var {
        match (self.0, other.0) {
            (Value::Const(a), Value::Const(b)) => constant(a + b),
            (Value::Node(a), Value::Const(c)) | (Value::Const(c), Value::Node(a)) => {
                if c == 0.0 {
                    self_or(a)
                } else {
                    record(Node::AddC(a, c.to_bits()))
                }
            }
            (Value::Node(a), Value::Node(b)) => record(Node::Add(a.min(b), a.max(b))),
        }
    }
}

fn self_or(a: u32) -> Var {
    Var(Value::Node(a))
}

impl Sub for Var {
    type Output = Var;
    fn sub(self, other: Var) -> Var {
        match (self.0, other.0) {
            (Value::Const(a), Value::Const(b)) => constant(a - b),
            // a - c = a + (-c) exactly in IEEE arithmetic.
            (Value::Node(_), Value::Const(c)) => self + constant(-c),
            (Value::Const(c), Value::Node(a)) => record(Node::CSub(c.to_bits(), a)),
            (Value::Node(a), Value::Node(b)) => record(Node::Sub(a, b)),
        }
    }
}

impl Mul for Var {
    type Output = Var;
    fn mul(self, other: Var) -> Var {
        match (self.0, other.0) {
            (Value::Const(a), Value::Const(b)) => constant(a * b),
            (Value::Node(a), Value::Const(c)) | (Value::Const(c), Value::Node(a)) => {
                if c == 0.0 {
                    constant(0.0)
                } else if c == 1.0 {
                    self_or(a)
                } else if c == -1.0 {
                    record(Node::Neg(a))
                } else {
                    record(Node::MulC(a, c.to_bits()))
                }
            }
            (Value::Node(a), Value::Node(b)) => record(Node::Mul(a.min(b), a.max(b))),
        }
    }
}

impl Div for Var {
    type Output = Var;
    fn div(self, other: Var) -> Var {
        match (self.0, other.0) {
            (Value::Const(a), Value::Const(b)) => constant(a / b),
            (Value::Node(a), Value::Const(c)) => {
                if c == 1.0 {
                    self_or(a)
                } else {
                    record(Node::DivC(a, c.to_bits()))
                }
            }
            (Value::Const(c), Value::Node(a)) => record(Node::CDiv(c.to_bits(), a)),
            (Value::Node(a), Value::Node(b)) => record(Node::Div(a, b)),
        }
    }
}

impl Neg for Var {
    type Output = Var;
    fn neg(self) -> Var {
        match self.0 {
            Value::Const(c) => constant(-c),
            Value::Node(a) => record(Node::Neg(a)),
        }
    }
}

impl Add<f64> for Var {
    type Output = Var;
    fn add(self, c: f64) -> Var {
        self + constant(c)
    }
}

impl Sub<f64> for Var {
    type Output = Var;
    fn sub(self, c: f64) -> Var {
        self - constant(c)
    }
}

impl Mul<f64> for Var {
    type Output = Var;
    fn mul(self, c: f64) -> Var {
        self * constant(c)
    }
}

impl Div<f64> for Var {
    type Output = Var;
    fn div(self, c: f64) -> Var {
        self / constant(c)
    }
}

impl Scalar for Var {
    fn from_f64(c: f64) -> Self {
        constant(c)
    }

    fn sqrt(self) -> Self {
        match self.0 {
            Value::Const(c) => constant(c.sqrt()),
            Value::Node(a) => record(Node::Sqrt(a)),
        }
    }

    /// `1 / self`, as `f64::recip` computes it.
    fn recip(self) -> Self {
        constant(1.0) / self
    }

    /// Fused exactly where `f64`'s [`Scalar::mul_add`] is (targets with an FMA instruction),
    /// so that order 0 of the tape is the `f64` field bit for bit.
    fn mul_add(self, a: Self, b: Self) -> Self {
        if !cfg!(target_feature = "fma") {
            return self * a + b;
        }
        match (self.0, a.0, b.0) {
            (Value::Const(x), Value::Const(y), Value::Const(z)) => constant(x.mul_add(y, z)),
            _ => record(Node::MulAdd(self.as_node(), a.as_node(), b.as_node())),
        }
    }
}

/// One operation of the compiled tape; its result goes to slot `first_op + position`.
/// Operands are the offsets `slot * stride` of their coefficients; constants inline.
#[derive(Debug, Clone, Copy)]
pub(super) enum Instr {
    Add(u32, u32),
    Sub(u32, u32),
    Mul(u32, u32),
    Div(u32, u32),
    Neg(u32),
    Sqrt(u32),
    MulAdd(u32, u32, u32),
    AddC(u32, f64),
    CSub(f64, u32),
    MulC(u32, f64),
    DivC(u32, f64),
    CDiv(f64, u32),
    /// `a b + c d` (products used only here).
    DotAdd(u32, u32, u32, u32),
    /// `a b - c d`.
    DotSub(u32, u32, u32, u32),
    /// `a b + c`.
    MulPlus(u32, u32, u32),
    /// `a b - c`.
    MulMinus(u32, u32, u32),
    /// `c - a b`.
    MinusMul(u32, u32, u32),
}

impl Instr {
    /// The operation's name, its operand slots and whether it has an inline constant.
    pub(super) fn parts(&self) -> (&'static str, Vec<u32>, bool) {
        match *self {
            Instr::Add(a, b) => ("add", vec![a, b], false),
            Instr::Sub(a, b) => ("sub", vec![a, b], false),
            Instr::Mul(a, b) => ("mul", vec![a, b], false),
            Instr::Div(a, b) => ("div", vec![a, b], false),
            Instr::Neg(a) => ("neg", vec![a], false),
            Instr::Sqrt(a) => ("sqrt", vec![a], false),
            Instr::MulAdd(a, b, d) => ("mul_add", vec![a, b, d], false),
            Instr::AddC(a, _) => ("add_c", vec![a], true),
            Instr::CSub(_, a) => ("c_sub", vec![a], true),
            Instr::MulC(a, _) => ("mul_c", vec![a], true),
            Instr::DivC(a, _) => ("div_c", vec![a], true),
            Instr::CDiv(_, a) => ("c_div", vec![a], true),
            Instr::DotAdd(a, b, d, e) => ("dot_add", vec![a, b, d, e], false),
            Instr::DotSub(a, b, d, e) => ("dot_sub", vec![a, b, d, e], false),
            Instr::MulPlus(a, b, d) => ("mul_plus", vec![a, b, d], false),
            Instr::MulMinus(a, b, d) => ("mul_minus", vec![a, b, d], false),
            Instr::MinusMul(d, a, b) => ("minus_mul", vec![d, a, b], false),
        }
    }

    /// The inline constant of [`Instr::AddC`], [`Instr::CSub`], [`Instr::MulC`],
    /// [`Instr::DivC`] and [`Instr::CDiv`].
    fn constant(&self) -> Option<f64> {
        match *self {
            Instr::AddC(_, k)
            | Instr::CSub(k, _)
            | Instr::MulC(_, k)
            | Instr::DivC(_, k)
            | Instr::CDiv(k, _) => Some(k),
            _ => None,
        }
    }
}

/// The instruction set the expansion runs in, detected at run time ([`Isa::detect`]). The
/// orders `k >= 1` fuse their multiply-adds with AVX2 or AVX-512 alike: the arithmetic of a lane
/// does not depend on how many lanes run beside it, nor on the width of the registers.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Isa {
    /// The target's baseline (x86-64: SSE2, two doubles a register): products and sums apart.
    Baseline,
    /// AVX2 and FMA: four doubles a register, fused multiply-adds in the orders `k >= 1`.
    Avx2Fma,
    /// AVX-512F and VL with AVX2 and FMA: eight doubles a register and 32 registers for
    /// every width (VL: for 1, 2 and 4 doubles too), fused multiply-adds in the orders `k >= 1`.
    Avx512,
}

impl Isa {
    /// The widest of the three that this CPU has.
    pub fn detect() -> Isa {
        #[cfg(target_arch = "x86_64")]
        {
            use std::arch::is_x86_feature_detected as has;
            if has!("avx2") && has!("fma") {
                return if has!("avx512f") && has!("avx512vl") {
                    Isa::Avx512
                } else {
                    Isa::Avx2Fma
                };
            }
        }
        Isa::Baseline
    }

    /// Whether this CPU has the set: the baseline always, AVX2 with FMA when
    /// [`Isa::detect`] finds it or AVX-512, AVX-512 when it finds AVX-512.
    pub fn available(self) -> bool {
        match self {
            Isa::Baseline => true,
            Isa::Avx2Fma => Isa::detect() != Isa::Baseline,
            Isa::Avx512 => Isa::detect() == Isa::Avx512,
        }
    }

    /// The number of doubles in one vector register.
    pub fn doubles(self) -> usize {
        match self {
            Isa::Baseline => 2,
            Isa::Avx2Fma => 4,
            Isa::Avx512 => 8,
        }
    }
}

/// The instruction sets whose copies of a loop are compiled in: AVX-512 if `AVX512`, AVX2
/// with FMA if `AVX2`, the baseline if `BASE` (a copy not compiled costs no build time: the
/// loops of the lanes and the expansions of the tape are the largest code of the crates that
/// run lanes). What runs in production is one width per instruction set
/// ([`crate::batch::lanes`], [`crate::batch::taylor::lanes`]), so its entry points compile
/// only the sets of that width; the entry points that take the set (tests, benchmarks)
/// compile all three.
pub(crate) struct Compiled<const AVX512: bool, const AVX2: bool, const BASE: bool>;

/// Every set compiled in.
pub(crate) type All = Compiled<true, true, true>;

/// The sets compiled in, as the loops and expansions read them ([`Compiled`]).
pub(crate) trait Sets {
    /// AVX-512's copy is compiled in.
    const AVX512: bool;
    /// AVX2's (with FMA) copy is compiled in.
    const AVX2: bool;
    /// The baseline's copy is compiled in (always on other architectures than x86-64, where
    /// [`Isa::detect`] finds only the baseline).
    const BASELINE: bool;

    /// The set that runs what asks for `isa`: `isa` if compiled in, else the widest set
    /// compiled in that is narrower, else (none is) the narrowest compiled in, which the
    /// callers check the CPU has.
    fn run_as(isa: Isa) -> Isa {
        match isa {
            Isa::Avx512 if Self::AVX512 => Isa::Avx512,
            Isa::Avx512 | Isa::Avx2Fma if Self::AVX2 => Isa::Avx2Fma,
            _ if Self::BASELINE => Isa::Baseline,
            _ if Self::AVX2 => Isa::Avx2Fma,
            _ => Isa::Avx512,
        }
    }
}

impl<const AVX512: bool, const AVX2: bool, const BASE: bool> Sets for Compiled<AVX512, AVX2, BASE> {
    const AVX512: bool = AVX512;
    const AVX2: bool = AVX2;
    const BASELINE: bool = BASE || cfg!(not(target_arch = "x86_64"));
}

/// A field `y' = f(t, y)` of dimension `N` as a compiled expression tape, with the storage of
/// the Taylor coefficients (of type `T`: [`Coefficient`]) of all its slots up to order
/// `max_order`.
#[derive(Debug, Clone)]
pub struct Tape<const N: usize, T = f64, K = Interpreted> {
    code: Vec<Instr>,
    /// Slot of the time.
    time: usize,
    /// First slot written by `code`; the constants are the slots `N + 1 .. first_op`.
    first_op: usize,
    /// Slot of each output component `f_i`.
    outputs: [usize; N],
    /// The values of the constants, in slot order.
    constants: Vec<f64>,
    /// Coefficients per slot: `coef[s * stride + PAD + k] = x_s^[k]`, `k <= max_order`,
    /// between `PAD` places on either side (and at least [`STRIDE`] places a slot).
    coef: Vec<T>,
    max_order: usize,
    /// `PAD + max_order + 1 + PAD`, at least [`STRIDE`].
    stride: usize,
    /// The instruction set of the orders `k >= 1` (and whether their multiply-adds fuse).
    isa: Isa,
    /// The history of each instruction with a product, quotient or square root, in the order
    /// of `code` ([`convolution`]).
    hist: Vec<History>,
    /// Their values at the order of the pass under way.
    hval: Vec<T>,
    /// The terms of the next order that the generated histories summed with those of an even
    /// order ([`super::codegen`]).
    hnext: Vec<T>,
    /// The generated kernel of the tape's shape, if there is one ([`super::codegen`]).
    kernel: Option<usize>,
    /// The inline constants the kernel takes, those of the instructions in their order
    /// ([`Instr::constant`]; the orders `k >= 1` read only the factors and divisors of
    /// [`Instr::MulC`] and [`Instr::DivC`]).
    inline: Vec<f64>,
    /// The generated kernels among which [`Tape::record`] looks for this tape's shape.
    kernels: PhantomData<fn() -> K>,
}

/// Places before and after each slot's coefficients (see [`Tape`]), which nothing reads (the
/// margin of vector loads that read around a slot, which the histories no longer make).
pub const PAD: usize = 4;

/// The places of a slot up to order 24, `PAD + 25 + PAD` (orders 20 and below at the
/// tolerances from 1e-12 down to 2.2e-16): a constant, so that the generated kernels address
/// every coefficient at a fixed distance from order `k` of the first slot (no product of a slot
/// by a variable stride per operand: the Taylor lanes and the one-at-a-time Taylor method
/// run about 5 % faster, BENCHMARKS.md). Odd: with 32 places, slots 2 KiB apart in 8 lanes, the
/// same order of every slot fell into the same few sets of the L1 cache (the lanes 20 % slower
/// than with a variable stride). The places above a tape's order are never read; a tape of a
/// higher order has the places it needs, and runs in the interpreter (the generated kernels
/// are compiled for this stride alone: one copy of each, not two).
pub const STRIDE: usize = 33;

impl<const N: usize, K: Kernels> Tape<N, f64, K> {
    /// The shape of the tape: its dimension, its first operation's slot and its operations
    /// (name, operand slots, `#` for an inline constant), one per line, the constants left out.
    /// Two tapes of the same shape run the same generated kernel ([`Kernels::SHAPES`]).
    pub fn shape(&self) -> String {
        let mut text = format!("n {N} first {}\n", self.first_op);
        for instr in &self.code {
            let (name, operands, constant) = instr.parts();
            text.push_str(name);
            for a in operands {
                write!(text, " {}", self.slot_of(a)).expect("writing to a String");
            }
            if constant {
                text.push_str(" #");
            }
            text.push('\n');
        }
        text
    }

    /// Records the field of `sys` ([`OdeSystem::record`]) and compiles it, with room for Taylor
    /// coefficients up to order `max_order`, run by the kernel of its shape among the system's
    /// [`OdeSystem::Kernels`] if there is one. `None` if the system cannot be recorded.
    pub fn record<S: OdeSystem<N, Kernels = K> + ?Sized>(
        sys: &S,
        max_order: usize,
    ) -> Option<Self> {
        RECORDERS.with(|r| r.borrow_mut().push(Recorder::default()));
        let inputs: [Var; N] = std::array::from_fn(|i| record(Node::Input(i as u32)));
        let time = record(Node::Time);
        let outputs = sys.record(time, &inputs);
        let outputs = outputs.map(|out| out.map(Var::as_node));
        let recorder = RECORDERS.with(|r| r.borrow_mut().pop().expect("pushed above"));
        outputs.map(|out| Self::compile(&recorder.nodes, &out, max_order))
    }

    /// Lays the nodes that `outputs` depend on out in slots and builds the instruction array.
    fn compile(nodes: &[Node], outputs: &[u32; N], max_order: usize) -> Self {
        let mut live = vec![false; nodes.len()];
        for &o in outputs {
            live[o as usize] = true;
        }
        for i in (0..nodes.len()).rev() {
            if live[i] {
                for operand in operands(&nodes[i]) {
                    live[operand as usize] = true;
                }
            }
        }
        // Slots: inputs 0..N, time N, then constants, then operations in recording order
        // (which is topological: operands are recorded before their uses).
        let mut slot = vec![usize::MAX; nodes.len()];
        let mut constants = vec![];
        let mut ops = vec![];
        for (i, node) in nodes.iter().enumerate() {
            match *node {
                Node::Input(k) => slot[i] = k as usize,
                Node::Time => slot[i] = N,
                Node::Const(bits) if live[i] => constants.push((i, f64::from_bits(bits))),
                _ if live[i] => ops.push(i),
                _ => {}
            }
        }
        // Fusion: a product used only by one sum or difference is computed inside it.
        let mut uses = vec![0usize; nodes.len()];
        for (i, node) in nodes.iter().enumerate() {
            if live[i] {
                operands(node).for_each(|o| uses[o as usize] += 1);
            }
        }
        outputs.iter().for_each(|&o| uses[o as usize] += 2);
        let product = |x: u32| match nodes[x as usize] {
            Node::Mul(a, b) if uses[x as usize] == 1 => Some((a, b)),
            _ => None,
        };
        let mut fused = vec![None; nodes.len()];
        for (i, node) in nodes.iter().enumerate() {
            if !live[i] {
                continue;
            }
            let (x, y, minus) = match *node {
                Node::Add(x, y) => (x, y, false),
                Node::Sub(x, y) => (x, y, true),
                _ => continue,
            };
            let instr = match (product(x), product(y), minus) {
                (Some((a, b)), Some((c, d)), false) => Fused::DotAdd(a, b, c, d),
                (Some((a, b)), Some((c, d)), true) => Fused::DotSub(a, b, c, d),
                (Some((a, b)), None, false) => Fused::MulPlus(a, b, y),
                (None, Some((a, b)), false) => Fused::MulPlus(a, b, x),
                (Some((a, b)), None, true) => Fused::MulMinus(a, b, y),
                (None, Some((a, b)), true) => Fused::MinusMul(x, a, b),
                (None, None, _) => continue,
            };
            for z in [x, y] {
                if product(z).is_some() {
                    live[z as usize] = false;
                }
            }
            fused[i] = Some(instr);
        }
        ops.retain(|&i| live[i]);
        let first_op = N + 1 + constants.len();
        for (j, &(i, _)) in constants.iter().enumerate() {
            slot[i] = N + 1 + j;
        }
        for (j, &i) in ops.iter().enumerate() {
            slot[i] = first_op + j;
        }
        let stride = (PAD + max_order + 1 + PAD).max(STRIDE);
        let s = |a: u32| (slot[a as usize] * stride + PAD) as u32;
        let code = ops
            .iter()
            .map(|&i| match (fused[i], nodes[i]) {
                (Some(Fused::DotAdd(a, b, c, d)), _) => Instr::DotAdd(s(a), s(b), s(c), s(d)),
                (Some(Fused::DotSub(a, b, c, d)), _) => Instr::DotSub(s(a), s(b), s(c), s(d)),
                (Some(Fused::MulPlus(a, b, c)), _) => Instr::MulPlus(s(a), s(b), s(c)),
                (Some(Fused::MulMinus(a, b, c)), _) => Instr::MulMinus(s(a), s(b), s(c)),
                (Some(Fused::MinusMul(c, a, b)), _) => Instr::MinusMul(s(c), s(a), s(b)),
                (None, node) => match node {
                    Node::Add(a, b) => Instr::Add(s(a), s(b)),
                    Node::Sub(a, b) => Instr::Sub(s(a), s(b)),
                    Node::Mul(a, b) => Instr::Mul(s(a), s(b)),
                    Node::Div(a, b) => Instr::Div(s(a), s(b)),
                    Node::Neg(a) => Instr::Neg(s(a)),
                    Node::Sqrt(a) => Instr::Sqrt(s(a)),
                    Node::MulAdd(a, b, c) => Instr::MulAdd(s(a), s(b), s(c)),
                    Node::AddC(a, c) => Instr::AddC(s(a), f64::from_bits(c)),
                    Node::CSub(c, a) => Instr::CSub(f64::from_bits(c), s(a)),
                    Node::MulC(a, c) => Instr::MulC(s(a), f64::from_bits(c)),
                    Node::DivC(a, c) => Instr::DivC(s(a), f64::from_bits(c)),
                    Node::CDiv(c, a) => Instr::CDiv(f64::from_bits(c), s(a)),
                    Node::Input(_) | Node::Time | Node::Const(_) => {
                        unreachable!("not an operation")
                    }
                },
            })
            .collect::<Vec<_>>();
        let tape: Tape<N, f64, K> = Tape {
            code,
            time: N,
            first_op,
            outputs: outputs.map(|o| slot[o as usize]),
            constants: constants.iter().map(|&(_, c)| c).collect(),
            coef: vec![],
            max_order,
            stride,
            isa: Isa::detect(),
            hist: vec![],
            hval: vec![],
            hnext: vec![],
            kernel: None,
            inline: vec![],
            kernels: PhantomData,
        };
        let hist = histories(&tape.code, (first_op * stride + PAD) as u32, stride);
        // A kernel addresses its coefficients at the constant stride only: a tape of a higher
        // order (above 24, tolerances below about 1e-20) runs in the interpreter, bitwise the
        // same coefficients.
        let shape = tape.shape();
        let kernel = (stride == STRIDE)
            .then(|| K::SHAPES.iter().position(|(_, s)| *s == shape))
            .flatten();
        let inline = tape.code.iter().filter_map(Instr::constant).collect();
        Tape {
            hist,
            kernel,
            inline,
            ..tape
        }
        .with_coefficients()
    }
}

impl<const N: usize, T: Coefficient, K: Kernels> Tape<N, T, K> {
    /// The same tape with the coefficient storage of type `U` (e.g. [`Lanes`](crate::batch::Lanes)
    /// to expand several runs at once), every coefficient zero but the constants.
    pub fn with_coefficients<U: Coefficient>(&self) -> Tape<N, U, K> {
        let zero = U::from_f64(0.0);
        let size = (self.first_op + self.code.len()) * self.stride;
        let mut tape = Tape {
            code: self.code.clone(),
            time: self.time,
            first_op: self.first_op,
            outputs: self.outputs,
            constants: self.constants.clone(),
            coef: vec![zero; size],
            max_order: self.max_order,
            stride: self.stride,
            isa: self.isa,
            hist: self.hist.clone(),
            hval: vec![zero; self.hist.len()],
            hnext: vec![zero; self.hist.len()],
            kernel: self.kernel,
            inline: self.inline.clone(),
            kernels: PhantomData,
        };
        for j in 0..tape.constants.len() {
            tape.set(N + 1 + j, 0, U::from_f64(tape.constants[j]));
        }
        tape
    }

    /// The compiled instructions.
    pub(super) fn code(&self) -> &[Instr] {
        &self.code
    }

    /// The histories of the instructions with a product, quotient or square root
    /// ([`convolution`]), in the order of [`Tape::code`].
    pub(super) fn history_list(&self) -> &[History] {
        &self.hist
    }

    /// The slot of the first operation.
    pub(super) fn first_op(&self) -> usize {
        self.first_op
    }

    /// The slot of the coefficient at `at` in the coefficient storage (as the instructions'
    /// operands are written: order 0 of the slot).
    pub(super) fn slot_of(&self, at: u32) -> usize {
        (at as usize - PAD) / self.stride
    }

    /// The number of places of a slot.
    pub fn stride(&self) -> usize {
        self.stride
    }

    /// The name of the generated kernel that runs this tape's passes (`taylor::codegen`),
    /// `None` if the interpreter runs them (no kernel of the tape's shape, or an order above
    /// the constant [`STRIDE`]'s).
    pub fn kernel(&self) -> Option<&'static str> {
        self.kernel.map(|i| K::SHAPES[i].0)
    }

    /// The same tape run in the instruction set `isa` (which the CPU must have).
    pub fn with_isa(&self, isa: Isa) -> Self {
        Tape {
            isa,
            ..self.clone()
        }
    }

    /// The same tape run by the interpreter (to compare a kernel with it).
    pub fn interpreted(&self) -> Self {
        Tape {
            kernel: None,
            ..self.clone()
        }
    }

    /// The instruction set the expansion runs in (detected when the tape was recorded).
    pub fn isa(&self) -> Isa {
        self.isa
    }
    /// Number of operations on the compiled tape.
    pub fn len(&self) -> usize {
        self.code.len()
    }

    /// Whether the tape has no operation (the field is a constant or a copy of its inputs).
    pub fn is_empty(&self) -> bool {
        self.code.is_empty()
    }

    /// Number of instructions with a product, quotient or square root (the operations of cost
    /// `O(k)` at order `k`).
    pub fn nonlinear_len(&self) -> usize {
        // One history each (`histories`).
        self.hist.len()
    }

    /// The highest order the coefficient storage holds.
    pub fn max_order(&self) -> usize {
        self.max_order
    }

    /// The field `f(t, y)` from the tape (order 0 of the recurrences): the same numbers, bit
    /// for bit, as the `f64` field it was recorded from (in each lane).
    pub fn evaluate(&mut self, t: T, y: &[T; N]) -> [T; N] {
        self.seed(t, y);
        self.order_zero();
        self.outputs.map(|o| self.coef[self.base(o)])
    }

    /// Taylor coefficients `y^[0..=p]` of the solution through `(t, y)` (in each lane): on
    /// return, [`Tape::state_coefficient`]`(i, k)` holds `y_i^[k]` for `k <= p`
    /// (`p <= max_order`). From `y^[k+1] = f^[k] / (k + 1)`: one pass of the tape per order.
    ///
    /// A lane whose series is not finite is cleared ([`Tape::clear_lane`]) and its state
    /// coefficients `y^[0..=p]` set to NaN, so that a step taken from them is NaN (its
    /// integrator reports it); expanding that lane again gives NaN until it is cleared.
    pub fn expand(&mut self, t: T, y: &[T; N], p: usize) {
        self.expand_among::<All>(t, y, p);
    }

    /// [`Tape::expand`] with only the copies for the sets `S` compiled in ([`Compiled`]):
    /// the tape's set ([`Isa::detect`] when it was recorded) must be one of them, as the
    /// expansions of the sets differ in their fused multiply-adds.
    #[inline(always)]
    pub(crate) fn expand_among<S: Sets>(&mut self, t: T, y: &[T; N], p: usize) {
        assert!(
            S::run_as(self.isa) == self.isa,
            "the expansion for {:?} is not compiled in",
            self.isa
        );
        #[cfg(target_arch = "x86_64")]
        match self.isa {
            // SAFETY: `isa` comes from `Isa::detect`: the CPU has the features each function
            // is compiled for.
            Isa::Avx512 if S::AVX512 => return unsafe { self.expand_avx512(t, y, p) },
            Isa::Avx2Fma if S::AVX2 => return unsafe { self.expand_avx2_fma(t, y, p) },
            _ => {}
        }
        if S::BASELINE {
            self.expand_baseline(t, y, p);
        }
    }

    // Each set's expansion is a function of its own, never inlined into its caller: the loops
    // of the lanes are compiled once for each set they run in (`batch::Runs::integrate`), and
    // an expansion inlined there would be compiled again inside each copy of the loop, every
    // set's inside every set's (a test binary that runs the three sets' loops: 354 s of CPU
    // against 108 s, 2026-12-02). The call costs nothing beside an expansion's work.

    /// [`Tape::expand`] in the baseline set (SSE2 on x86-64), without fused multiply-adds.
    #[inline(never)]
    fn expand_baseline(&mut self, t: T, y: &[T; N], p: usize) {
        self.expand_with::<false, false>(t, y, p);
    }

    /// [`Tape::expand`] compiled for AVX2 and FMA.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    #[inline(never)]
    fn expand_avx2_fma(&mut self, t: T, y: &[T; N], p: usize) {
        self.expand_with::<true, false>(t, y, p);
    }

    /// [`Tape::expand`] compiled for AVX-512F and VL (and AVX2, FMA).
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx512f,avx512vl,avx2,fma")]
    #[inline(never)]
    fn expand_avx512(&mut self, t: T, y: &[T; N], p: usize) {
        // The histories of two orders at a time in `f64` and 8 lanes; one at a time in 4 lanes
        // (in registers of 4 doubles this Zen 4 loads two a cycle: the loads saved did not
        // pay, 1.12x slower at order 15; BENCHMARKS.md, "Sweeps").
        if T::WIDTH == 4 {
            self.expand_with::<true, false>(t, y, p);
        } else {
            self.expand_with::<true, true>(t, y, p);
        }
    }

    /// [`Tape::expand`], with fused multiply-adds in the orders `k >= 1` if `FMA`.
    #[inline(always)]
    fn expand_with<const FMA: bool, const WIDE: bool>(&mut self, t: T, y: &[T; N], p: usize) {
        assert!(
            p <= self.max_order,
            "order {p} above the tape's {}",
            self.max_order
        );
        self.seed(t, y);
        for k in 0..p {
            if k == 0 {
                self.order_zero();
            } else {
                self.order::<FMA, WIDE>(k);
            }
            let inv = 1.0 / (k + 1) as f64;
            for i in 0..N {
                let f = self.coef[self.base(self.outputs[i]) + k];
                self.set(i, k + 1, f * inv);
            }
        }
        // A lane whose state series is not finite is cleared and its series set to NaN: its
        // integrator refuses the step, and the lane's next run starts as on a new tape. `x * 0`
        // is NaN for a non-finite `x` and zero otherwise: one vector sum finds the lanes.
        let mut probe = T::from_f64(0.0);
        for i in 0..N {
            for &v in self.state_series(i, p) {
                probe = probe + v * 0.0;
            }
        }
        for l in (0..T::WIDTH).filter(|&l| !probe.lane(l).is_finite()) {
            self.clear_lane(l);
            for i in 0..N {
                for k in 0..=p {
                    let at = self.base(i) + k;
                    self.coef[at].set_lane(l, f64::NAN);
                }
            }
        }
    }

    /// Sets every coefficient of lane `l` to zero but the constants': the lane is then as in
    /// a new tape (for a new run in that lane; the results of an expansion depend on the
    /// previous one's only through zeros, whose signs this makes those of a new tape).
    ///
    /// Only the places of orders `0 ..= max_order` of each slot: the places around them are
    /// never written (zero since the tape was made).
    pub fn clear_lane(&mut self, l: usize) {
        let (stride, orders) = (self.stride, self.max_order + 1);
        let slots = (0..=N).chain(self.first_op..self.coef.len() / stride);
        for slot in slots {
            let at = slot * stride + PAD;
            for v in &mut self.coef[at..at + orders] {
                v.set_lane(l, 0.0);
            }
        }
    }

    /// `y_i^[k]` after [`Tape::expand`].
    #[inline(always)]
    pub fn state_coefficient(&self, i: usize, k: usize) -> T {
        self.coef[self.base(i) + k]
    }

    /// The coefficients `y_i^[0..=p]` after [`Tape::expand`].
    #[inline(always)]
    pub fn state_series(&self, i: usize, p: usize) -> &[T] {
        &self.coef[self.base(i)..=self.base(i) + p]
    }

    /// Where `x_slot^[0]` is in `coef`.
    #[inline(always)]
    fn base(&self, slot: usize) -> usize {
        slot * self.stride + PAD
    }

    /// Stores `x_slot^[k]`.
    #[inline(always)]
    fn set(&mut self, slot: usize, k: usize, value: T) {
        let at = self.base(slot) + k;
        self.coef[at] = value;
    }

    #[inline(always)]
    fn seed(&mut self, t: T, y: &[T; N]) {
        for (i, &v) in y.iter().enumerate() {
            self.set(i, 0, v);
        }
        self.set(self.time, 0, t);
        if self.max_order > 0 {
            self.set(self.time, 1, T::from_f64(1.0));
        }
    }

    /// Order 0 of every operation: the `f64` operations of the field themselves (in the
    /// generated kernel's straight-line code if the tape has one, the same operations).
    #[inline(always)]
    fn order_zero(&mut self) {
        if let Some(kernel) = self.kernel {
            K::zero(kernel, &mut self.coef, STRIDE, &self.inline);
            return;
        }
        // Slices held in locals: the stores below cannot make the compiler reload them.
        let (code, c) = (&self.code[..], &mut self.coef[..]);
        let stride = self.stride;
        let lift = T::from_f64;
        for (j, instr) in code.iter().enumerate() {
            let value = match *instr {
                Instr::Add(a, b) => c[a as usize] + c[b as usize],
                Instr::Sub(a, b) => c[a as usize] - c[b as usize],
                Instr::Mul(a, b) => c[a as usize] * c[b as usize],
                Instr::Div(a, b) => c[a as usize] / c[b as usize],
                Instr::Neg(a) => -c[a as usize],
                Instr::Sqrt(a) => c[a as usize].sqrt(),
                Instr::MulAdd(a, b, d) => c[a as usize].mul_add(c[b as usize], c[d as usize]),
                Instr::AddC(a, k) => c[a as usize] + k,
                Instr::CSub(k, a) => lift(k) - c[a as usize],
                Instr::MulC(a, k) => c[a as usize] * k,
                Instr::DivC(a, k) => c[a as usize] / k,
                Instr::CDiv(k, a) => lift(k) / c[a as usize],
                Instr::DotAdd(a, b, d, e) => {
                    c[a as usize] * c[b as usize] + c[d as usize] * c[e as usize]
                }
                Instr::DotSub(a, b, d, e) => {
                    c[a as usize] * c[b as usize] - c[d as usize] * c[e as usize]
                }
                Instr::MulPlus(a, b, d) => c[a as usize] * c[b as usize] + c[d as usize],
                Instr::MulMinus(a, b, d) => c[a as usize] * c[b as usize] - c[d as usize],
                Instr::MinusMul(d, a, b) => c[d as usize] - c[a as usize] * c[b as usize],
            };
            c[(self.first_op + j) * stride + PAD] = value;
        }
    }

    /// Order `k >= 1` of every operation, from the orders below `k` and order `k` of the
    /// inputs: the histories of the convolutions first ([`convolution`]: the terms of orders
    /// `1 .. k-1`, for all operations at once), then one pass through the tape that adds to
    /// each history the terms with order `k` or 0 of an operand ([`recurrence`]).
    #[inline(always)]
    fn order<const FMA: bool, const WIDE: bool>(&mut self, k: usize) {
        assert!(k >= 1 && k <= self.max_order);
        let stride = self.stride;
        if let Some(kernel) = self.kernel {
            let (c, h, q) = (&mut self.coef[..], &mut self.hval[..], &self.inline[..]);
            let g = &mut self.hnext[..];
            // A tape with a kernel has the constant stride (`Tape::record`).
            K::histories::<T, FMA, WIDE>(kernel, c, STRIDE, k, h, g);
            K::pass::<T, FMA>(kernel, c, STRIDE, k, h, q);
            return;
        }
        convolution::histories::<T, FMA>(&self.coef, &self.hist, k, &mut self.hval);
        // Slices held in locals: the stores below cannot make the compiler reload them.
        let (code, c, hval) = (&self.code[..], &mut self.coef[..], &self.hval[..]);
        let mut histories = hval.iter().copied();
        let mut dest = self.first_op * stride + PAD;
        for instr in code {
            let mut history = || histories.next().expect("a history per nonlinear operation");
            // Orders 0 and k of a slot.
            let at = |x: u32| (c[x as usize], c[x as usize + k]);
            let value = match *instr {
                Instr::Add(a, b) => c[a as usize + k] + c[b as usize + k],
                Instr::Sub(a, b) => c[a as usize + k] - c[b as usize + k],
                Instr::Neg(a) | Instr::CSub(_, a) => -c[a as usize + k],
                Instr::AddC(a, _) => c[a as usize + k],
                Instr::MulC(a, m) => c[a as usize + k] * m,
                Instr::DivC(a, m) => c[a as usize + k] / m,
                Instr::Mul(a, b) => {
                    let ((a0, ak), (b0, bk)) = (at(a), at(b));
                    recurrence::product::<T, FMA>(a0, ak, b0, bk, history())
                }
                Instr::MulAdd(a, b, d) | Instr::MulPlus(a, b, d) => {
                    let ((a0, ak), (b0, bk)) = (at(a), at(b));
                    let dk = c[d as usize + k];
                    recurrence::mul_plus::<T, FMA>(a0, ak, b0, bk, dk, history())
                }
                Instr::MulMinus(a, b, d) => {
                    let ((a0, ak), (b0, bk)) = (at(a), at(b));
                    let dk = c[d as usize + k];
                    recurrence::mul_minus::<T, FMA>(a0, ak, b0, bk, dk, history())
                }
                Instr::MinusMul(d, a, b) => {
                    let ((a0, ak), (b0, bk)) = (at(a), at(b));
                    let dk = c[d as usize + k];
                    recurrence::minus_mul::<T, FMA>(dk, a0, ak, b0, bk, history())
                }
                Instr::DotAdd(a, b, d, e) => {
                    let [(a0, ak), (b0, bk), (d0, dk), (e0, ek)] = [a, b, d, e].map(at);
                    recurrence::dot_add::<T, FMA>([a0, ak, b0, bk], [d0, dk, e0, ek], history())
                }
                Instr::DotSub(a, b, d, e) => {
                    let [(a0, ak), (b0, bk), (d0, dk), (e0, ek)] = [a, b, d, e].map(at);
                    recurrence::dot_sub::<T, FMA>([a0, ak, b0, bk], [d0, dk, e0, ek], history())
                }
                Instr::Div(a, b) => {
                    let (b0, bk) = at(b);
                    recurrence::quotient::<T, FMA>(c[a as usize + k], b0, bk, c[dest], history())
                }
                Instr::CDiv(_, b) => {
                    let (b0, bk) = at(b);
                    recurrence::reciprocal::<T, FMA>(b0, bk, c[dest], history())
                }
                Instr::Sqrt(a) => recurrence::square_root(c[a as usize + k], c[dest], history()),
            };
            c[dest + k] = value;
            dest += stride;
        }
    }
}

/// The histories ([`convolution`]) of the instructions of `code` with a product, quotient or
/// square root, in their order; `dest` is where the first instruction's coefficients start,
/// each next one `stride` further.
///
/// An operand that is [`Instr::AddC`] of a slot is read as that slot: its orders from 1 up
/// are the same numbers (a copy), and the generated histories load a slot's coefficient
/// once for all the products that read it ([`super::codegen`]).
fn histories(code: &[Instr], mut dest: u32, stride: usize) -> Vec<History> {
    let mut list = vec![];
    let mut copies: HashMap<u32, u32> = HashMap::new();
    for instr in code {
        let source = |a: u32| copies.get(&a).copied().unwrap_or(a);
        let one = |a, b| {
            Some(History {
                a: source(a),
                b: source(b),
                second: None,
            })
        };
        let history = match *instr {
            Instr::Mul(a, b)
            | Instr::MulAdd(a, b, _)
            | Instr::MulPlus(a, b, _)
            | Instr::MulMinus(a, b, _)
            | Instr::MinusMul(_, a, b) => one(a, b),
            Instr::DotAdd(a, b, d, e) | Instr::DotSub(a, b, d, e) => Some(History {
                a: source(a),
                b: source(b),
                second: Some((source(d), source(e), matches!(instr, Instr::DotSub(..)))),
            }),
            // sum_{j=1..k-1} b^[j] w^[k-j]
            Instr::Div(_, b) | Instr::CDiv(_, b) => one(b, dest),
            // sum_{j=1..k-1} w^[j] w^[k-j]
            Instr::Sqrt(_) => one(dest, dest),
            Instr::Add(..)
            | Instr::Sub(..)
            | Instr::Neg(_)
            | Instr::AddC(..)
            | Instr::CSub(..)
            | Instr::MulC(..)
            | Instr::DivC(..) => None,
        };
        list.extend(history);
        if let Instr::AddC(a, _) = *instr {
            let a = source(a);
            copies.insert(dest, a);
        }
        dest += stride as u32;
    }
    list
}

/// A sum or difference with the products it absorbs (see [`Tape::compile`]); node indices.
#[derive(Debug, Clone, Copy)]
enum Fused {
    DotAdd(u32, u32, u32, u32),
    DotSub(u32, u32, u32, u32),
    MulPlus(u32, u32, u32),
    MulMinus(u32, u32, u32),
    MinusMul(u32, u32, u32),
}

/// The operand nodes of a node.
fn operands(node: &Node) -> impl Iterator<Item = u32> {
    let list: [Option<u32>; 3] = match *node {
        Node::Input(_) | Node::Time | Node::Const(_) => [None, None, None],
        Node::Add(a, b) | Node::Sub(a, b) | Node::Mul(a, b) | Node::Div(a, b) => {
            [Some(a), Some(b), None]
        }
        Node::Neg(a)
        | Node::Sqrt(a)
        | Node::AddC(a, _)
        | Node::CSub(_, a)
        | Node::MulC(a, _)
        | Node::DivC(a, _)
        | Node::CDiv(_, a) => [Some(a), None, None],
        Node::MulAdd(a, b, c) => [Some(a), Some(b), Some(c)],
    };
    list.into_iter().flatten()
}

#[cfg(test)]
mod tests {
    use super::{All, Compiled, Isa, Sets, Tape, Var};
    use crate::batch::Lanes;
    use crate::scalar::Scalar;
    use crate::OdeSystem;

    /// The set that runs what asks for a set is compiled in: the set asked for when that is
    /// compiled in, else the widest narrower one compiled, else the narrowest compiled (every
    /// choice of the flags with a set, every set asked for).
    #[test]
    fn a_set_runs_in_a_set_compiled_in() {
        fn check<S: Sets>() -> Vec<(Isa, Isa)> {
            [Isa::Baseline, Isa::Avx2Fma, Isa::Avx512]
                .map(|asked| (asked, S::run_as(asked)))
                .into()
        }
        let compiled = |run: Isa, flags: (bool, bool, bool)| match run {
            Isa::Avx512 => flags.0,
            Isa::Avx2Fma => flags.1,
            Isa::Baseline => flags.2 || cfg!(not(target_arch = "x86_64")),
        };
        let cases = [
            ((true, true, true), check::<All>()),
            ((true, true, false), check::<Compiled<true, true, false>>()),
            (
                (true, false, false),
                check::<Compiled<true, false, false>>(),
            ),
            ((false, true, true), check::<Compiled<false, true, true>>()),
            (
                (false, false, true),
                check::<Compiled<false, false, true>>(),
            ),
            (
                (false, true, false),
                check::<Compiled<false, true, false>>(),
            ),
        ];
        for (flags, runs) in cases {
            for (asked, run) in runs {
                assert!(compiled(run, flags), "{flags:?}: {asked:?} runs as {run:?}");
                let all = [Isa::Baseline, Isa::Avx2Fma, Isa::Avx512];
                let narrower = all
                    .into_iter()
                    .filter(|&s| compiled(s, flags) && s.doubles() <= asked.doubles())
                    .max_by_key(|s| s.doubles());
                let narrowest = all.into_iter().find(|&s| compiled(s, flags));
                assert_eq!(Some(run), narrower.or(narrowest), "{flags:?}: {asked:?}");
            }
        }
    }
    /// `y' = 1 / y`: not finite at `y = 0`.
    struct Inverse;

    impl OdeSystem<1> for Inverse {
        type Kernels = crate::taylor::Interpreted;

        fn rhs(&self, _t: f64, y: &[f64; 1]) -> [f64; 1] {
            [1.0 / y[0]]
        }

        fn record(&self, _t: Var, y: &[Var; 1]) -> Option<[Var; 1]> {
            Some([Scalar::recip(y[0])])
        }
    }

    /// Four runs expanded at once, one of them through `y = 0` where the field is infinite:
    /// that lane's state coefficients are all NaN up to the order (a step from them is NaN,
    /// which the integrators refuse), and the other lanes are bitwise an `f64` tape's
    /// (tolerance zero: the same operations). Cleared, the lane expands as a new tape does.
    /// Negative control: a lane through another state differs from the `f64` tape's.
    #[test]
    fn a_non_finite_lane_is_nan_and_leaves_the_others_alone() {
        let p = 6;
        let tape = Tape::record(&Inverse, p).expect("records");
        let mut lanes: Tape<1, Lanes<4>> = tape.with_coefficients();
        let single = |y: f64| {
            let mut one = tape.clone();
            one.expand(0.0, &[y], p);
            (0..=p)
                .map(|k| one.state_coefficient(0, k).to_bits())
                .collect::<Vec<_>>()
        };
        let lane = |lanes: &Tape<1, Lanes<4>>, l: usize| {
            (0..=p)
                .map(|k| lanes.state_coefficient(0, k).0[l].to_bits())
                .collect::<Vec<_>>()
        };
        let y = [1.0, 0.0, 2.0, -3.0];
        lanes.expand(Lanes::splat(0.0), &[Lanes(y)], p);
        for l in [0, 2, 3] {
            assert_eq!(lane(&lanes, l), single(y[l]), "lane {l}");
            assert!(single(y[l]).iter().all(|&b| f64::from_bits(b).is_finite()));
        }
        assert!((0..=p).all(|k| lanes.state_coefficient(0, k).0[1].is_nan()));
        assert_ne!(lane(&lanes, 0), single(1.5), "negative control");
        lanes.clear_lane(1);
        lanes.expand(Lanes::splat(0.0), &[Lanes([1.0, 0.5, 2.0, -3.0])], p);
        assert_eq!(lane(&lanes, 1), single(0.5));
    }
}
