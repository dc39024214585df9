//! The demo's report: `report.json` for scripts and `index.html` for people, one section per
//! paper with its pictures, 3-D viewer pages and data files, and a table of the paper's
//! figures beside ours with their ratio.
//!
//! The page is a static file with relative links only (it opens from the folder, no server,
//! no network). It is assembled with `format!` and a five-character HTML escape: a template
//! engine would be a larger dependency than the page.

use super::common::Finding;
use anyhow::Result;
use karkas_io::write::write_atomic;
use serde::Serialize;
use std::fmt::Write as _;
use std::path::Path;

/// What one example produced.
pub struct ExampleOutcome {
    /// The example's key for scripts.
    pub id: &'static str,
    /// The seed (paper) number.
    pub seed: &'static str,
    /// What the example shows.
    pub title: &'static str,
    /// Where our figures differ from the paper's and why, if they do.
    pub note: Option<&'static str>,
    /// How long it ran.
    pub seconds: f64,
    /// Its lines of the report.
    pub findings: Vec<Finding>,
    /// The names of the files it wrote.
    pub files: Vec<String>,
}

/// The papers, by seed number: the section titles of docs/methods.md.
const PAPERS: [(&str, &str); 6] = [
    (
        "000",
        "LL-approximation of curves and surfaces (Aulchenko, Latypov, Nikulichev)",
    ),
    (
        "001",
        "Generalized and composite Coons surfaces (Chashnikov)",
    ),
    (
        "002",
        "Discrete periodic splines with vector coefficients (Malozemov, Khorokhonov, Chashnikov)",
    ),
    (
        "003",
        "Cubic splines of defect 2 fitted with bounded second-derivative jumps (Pavlov)",
    ),
    (
        "004",
        "Parameterization and bicubic interpolation of surfaces (Kuznetsov, Filatov)",
    ),
    ("loft", "Lofting a wing through its sections (karkas)"),
];

/// `report.json`: the whole run.
#[derive(Serialize)]
struct JsonReport<'a> {
    karkas_version: &'a str,
    runtime_seconds: f64,
    examples: Vec<JsonExample<'a>>,
}

/// One example in `report.json`.
#[derive(Serialize)]
struct JsonExample<'a> {
    id: &'a str,
    seed: &'a str,
    paper: &'a str,
    title: &'a str,
    note: Option<&'a str>,
    seconds: f64,
    rows: Vec<JsonRow<'a>>,
    pictures: Vec<&'a str>,
    viewers: Vec<&'a str>,
    data: Vec<&'a str>,
}

/// One figure in `report.json`; `ratio` is karkas / paper.
#[derive(Serialize)]
struct JsonRow<'a> {
    example: &'a str,
    measure: &'a str,
    karkas: f64,
    paper: Option<f64>,
    ratio: Option<f64>,
}

fn paper_title(seed: &str) -> &'static str {
    PAPERS
        .iter()
        .find(|(s, _)| *s == seed)
        .map_or("", |(_, title)| title)
}

fn ratio(f: &Finding) -> Option<f64> {
    f.paper.filter(|&p| p != 0.0).map(|p| f.value / p)
}

/// The kind of an output file, by its extension.
#[derive(PartialEq, Clone, Copy)]
enum Kind {
    Picture,
    Viewer,
    Data,
}

fn kind(name: &str) -> Kind {
    let ext = name.rsplit('.').next().unwrap_or("");
    match ext {
        "svg" | "png" => Kind::Picture,
        "html" => Kind::Viewer,
        _ => Kind::Data,
    }
}

fn files_of(o: &ExampleOutcome, k: Kind) -> Vec<&str> {
    o.files
        .iter()
        .map(String::as_str)
        .filter(|n| kind(n) == k)
        .collect()
}

/// Writes `report.json`.
pub fn write_json(path: &Path, outcomes: &[ExampleOutcome], seconds: f64) -> Result<()> {
    let report = JsonReport {
        karkas_version: env!("CARGO_PKG_VERSION"),
        runtime_seconds: seconds,
        examples: outcomes
            .iter()
            .map(|o| JsonExample {
                id: o.id,
                seed: o.seed,
                paper: paper_title(o.seed),
                title: o.title,
                note: o.note,
                seconds: o.seconds,
                rows: o
                    .findings
                    .iter()
                    .map(|f| JsonRow {
                        example: &f.example,
                        measure: &f.measure,
                        karkas: f.value,
                        paper: f.paper,
                        ratio: ratio(f),
                    })
                    .collect(),
                pictures: files_of(o, Kind::Picture),
                viewers: files_of(o, Kind::Viewer),
                data: files_of(o, Kind::Data),
            })
            .collect(),
    };
    let text = serde_json::to_string_pretty(&report)?;
    write_atomic(path, |w| w.write_all(text.as_bytes()))?;
    Ok(())
}

/// `&`, `<`, `>`, `"` and `'` as entities.
fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => out.push(c),
        }
    }
    out
}

/// A figure for the page: three significant digits, exponent form outside 1e-3..1e4.
fn figure(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else if (1e-3..1e4).contains(&x.abs()) {
        format!("{:.4}", x)
            .trim_end_matches('0')
            .trim_end_matches('.')
            .into()
    } else {
        format!("{x:.3e}")
    }
}

const STYLE: &str = "body{font-family:system-ui,sans-serif;margin:2em auto;max-width:70em;\
padding:0 1em;color:#222}h1{margin-bottom:0}h2{border-bottom:1px solid #ccc;margin-top:2em}\
table{border-collapse:collapse;margin:1em 0;font-size:0.92em}\
th,td{border:1px solid #ccc;padding:0.25em 0.6em;text-align:left}\
td.n{text-align:right;font-variant-numeric:tabular-nums}th{background:#f3f3f3}\
figure{display:inline-block;margin:0.5em;vertical-align:top}\
figure img{max-width:32em;max-height:26em;border:1px solid #ddd;background:#fff}\
figcaption{font-size:0.85em;color:#555}.note{color:#555;font-style:italic}\
details{margin:0.5em 0}";

fn rows_table(html: &mut String, rows: &[&Finding], with_paper: bool) {
    html.push_str("<table>\n<tr><th>example</th><th>measure</th><th>karkas</th>");
    if with_paper {
        html.push_str("<th>paper</th><th>karkas / paper</th>");
    }
    html.push_str("</tr>\n");
    for f in rows {
        let _ = write!(
            html,
            "<tr><td>{}</td><td>{}</td><td class=\"n\">{}</td>",
            escape(&f.example),
            escape(&f.measure),
            figure(f.value)
        );
        if with_paper {
            let paper = f.paper.map_or_else(String::new, figure);
            let ratio = ratio(f).map_or_else(String::new, |r| format!("{r:.2}"));
            let _ = write!(
                html,
                "<td class=\"n\">{paper}</td><td class=\"n\">{ratio}</td>"
            );
        }
        html.push_str("</tr>\n");
    }
    html.push_str("</table>\n");
}

fn example_html(html: &mut String, o: &ExampleOutcome) {
    let _ = writeln!(
        html,
        "<h3 id=\"{id}\">{title}</h3>\n<p><code>{id}</code>, {seconds:.3} s</p>",
        id = escape(o.id),
        title = escape(o.title),
        seconds = o.seconds
    );
    if let Some(note) = o.note {
        let _ = writeln!(html, "<p class=\"note\">{}</p>", escape(note));
    }
    let (with_paper, checks): (Vec<&Finding>, Vec<&Finding>) =
        o.findings.iter().partition(|f| f.paper.is_some());
    if !with_paper.is_empty() {
        html.push_str("<p>The paper's figures beside karkas's:</p>\n");
        rows_table(html, &with_paper, true);
    }
    if !checks.is_empty() {
        html.push_str("<p>What karkas checks on this example:</p>\n");
        rows_table(html, &checks, false);
    }
    let pictures = files_of(o, Kind::Picture);
    for name in &pictures {
        // A PNG beside an SVG of the same picture is linked from the SVG's caption.
        let stem = name.rsplit_once('.').map_or(*name, |(s, _)| s);
        let png = format!("{stem}.png");
        if name.ends_with(".png") && pictures.contains(&format!("{stem}.svg").as_str()) {
            continue;
        }
        let also = if name.ends_with(".svg") && pictures.contains(&png.as_str()) {
            format!(" (<a href=\"{p}\">PNG</a>)", p = escape(&png))
        } else {
            String::new()
        };
        let _ = writeln!(
            html,
            "<figure><a href=\"{n}\"><img src=\"{n}\" alt=\"{n}\"></a>\
             <figcaption>{n}{also}</figcaption></figure>",
            n = escape(name)
        );
    }
    let viewers = files_of(o, Kind::Viewer);
    if !viewers.is_empty() {
        let _ = writeln!(html, "<p>3-D viewer pages: {}</p>", links(&viewers));
    }
    let data = files_of(o, Kind::Data);
    if !data.is_empty() {
        let _ = write!(
            html,
            "<details><summary>{} data and mesh files</summary><p>",
            data.len()
        );
        let _ = writeln!(html, "{}</p></details>", links(&data));
    }
}

/// Links to the files `names`, separated by commas.
fn links(names: &[&str]) -> String {
    let links: Vec<String> = names
        .iter()
        .map(|n| format!("<a href=\"{n}\">{n}</a>", n = escape(n)))
        .collect();
    links.join(", ")
}

/// Renders `index.html`.
pub fn render_html(outcomes: &[ExampleOutcome], seconds: f64) -> String {
    let mut html = String::new();
    let _ = writeln!(
        html,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <title>karkas demo: the five papers' examples</title>\n<style>{STYLE}</style>\n\
         </head>\n<body>\n<h1>karkas demo</h1>\n<p>Every example of the five papers behind \
         karkas, reproduced by <code>karkas demo</code> (version {}) in {seconds:.2} s, \
         and the loft of the shipped wing. \
         The numbers are also in <a href=\"report.json\">report.json</a>.</p>",
        env!("CARGO_PKG_VERSION")
    );
    let contents: String = PAPERS
        .iter()
        .map(|(seed, title)| {
            let title = escape(title);
            format!("<li><a href=\"#seed-{seed}\">{title}</a></li>\n")
        })
        .collect();
    let _ = write!(html, "<ul>\n{contents}</ul>\n");
    for (seed, title) in PAPERS {
        let _ = writeln!(html, "<h2 id=\"seed-{seed}\">{}</h2>", escape(title));
        for o in outcomes.iter().filter(|o| o.seed == seed) {
            example_html(&mut html, o);
        }
    }
    html.push_str("</body>\n</html>\n");
    html
}

/// Writes `index.html`.
pub fn write_html(path: &Path, outcomes: &[ExampleOutcome], seconds: f64) -> Result<()> {
    let html = render_html(outcomes, seconds);
    write_atomic(path, |w| w.write_all(html.as_bytes()))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn escape_replaces_the_five_characters() {
        assert_eq!(
            escape("a<b>&\"c\"'d'"),
            "a&lt;b&gt;&amp;&quot;c&quot;&#39;d&#39;"
        );
    }

    #[test]
    fn figures_are_short() {
        assert_eq!(figure(0.011), "0.011");
        assert_eq!(figure(0.0), "0");
        assert_eq!(figure(1.5e-15), "1.500e-15");
        assert_eq!(figure(8.19612), "8.1961");
    }

    #[test]
    fn files_are_sorted_by_kind() {
        assert!(kind("a.svg") == Kind::Picture);
        assert!(kind("a.png") == Kind::Picture);
        assert!(kind("a.html") == Kind::Viewer);
        assert!(kind("a.obj") == Kind::Data);
        assert!(kind("a.csv") == Kind::Data);
    }
}
