use pdesculpt::sasm::demo::female_fig10;

#[test]
fn scratch_fig10() {
    let d = female_fig10().unwrap();
    println!("{}", serde_json::to_string_pretty(&d.breast).unwrap());
    println!("{}", serde_json::to_string_pretty(&d.nose).unwrap());
    println!("{}", serde_json::to_string_pretty(&d.applied).unwrap());
    let c = pdesculpt::sasm::check::checks();
    for k in c {
        println!("{} {} {} {}", k.name, k.passed, k.measured, k.tolerance);
    }
}
