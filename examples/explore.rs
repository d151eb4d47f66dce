use routh::audit::claims::{audit, Sample};
fn main() {
    let v = audit(&Sample { seed: 1, count: 20 });
    print!("{}", routh::audit::report::table(&v));
}
