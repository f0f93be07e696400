//! SVG charts of the validation and benchmark results (plotters, SVG backend only).

use std::error::Error;
use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;

/// How a series is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mark {
    /// A line through the points.
    Line,
    /// A thin black line (theory curves).
    Theory,
    /// Filled circles (data).
    Points,
}

/// One labelled series.
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    /// Legend label.
    pub label: String,
    /// `(x, y)` points; non-finite ones are skipped.
    pub points: Vec<(f64, f64)>,
    /// How to draw it.
    pub mark: Mark,
}

impl Series {
    /// A series from a label, points and mark.
    pub fn new(label: impl Into<String>, points: Vec<(f64, f64)>, mark: Mark) -> Self {
        Self {
            label: label.into(),
            points: points
                .into_iter()
                .filter(|(x, y)| x.is_finite() && y.is_finite())
                .collect(),
            mark,
        }
    }
}

/// Axes of a chart.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Axes {
    /// Linear x and y.
    Linear,
    /// Logarithmic x and y (non-positive values are skipped).
    LogLog,
}

/// Draws `series` into an SVG file at `path`.
///
/// # Errors
/// From plotters or the file system.
pub fn chart(
    path: &Path,
    title: &str,
    (x_label, y_label): (&str, &str),
    series: &[Series],
    axes: Axes,
) -> Result<(), Box<dyn Error>> {
    let series: Vec<Series> = match axes {
        Axes::Linear => series.to_vec(),
        Axes::LogLog => series
            .iter()
            .map(|s| {
                let points = s
                    .points
                    .iter()
                    .copied()
                    .filter(|(x, y)| *x > 0.0 && *y > 0.0)
                    .collect();
                Series::new(s.label.clone(), points, s.mark)
            })
            .collect(),
    };
    let (x_range, y_range) = ranges(&series, axes);
    let root = SVGBackend::new(path, (900, 560)).into_drawing_area();
    root.fill(&WHITE)?;
    match axes {
        Axes::Linear => {
            let mut c = builder(&root, title)
                .build_cartesian_2d(x_range.0..x_range.1, y_range.0..y_range.1)?;
            c.configure_mesh().x_desc(x_label).y_desc(y_label).draw()?;
            draw(&mut c, &series)?;
        }
        Axes::LogLog => {
            let mut c = builder(&root, title).build_cartesian_2d(
                (x_range.0..x_range.1).log_scale(),
                (y_range.0..y_range.1).log_scale(),
            )?;
            c.configure_mesh().x_desc(x_label).y_desc(y_label).draw()?;
            draw(&mut c, &series)?;
        }
    }
    root.present()?;
    Ok(())
}

fn builder<'a, 'b>(
    root: &'a DrawingArea<SVGBackend<'b>, Shift>,
    title: &str,
) -> ChartBuilder<'a, 'b, SVGBackend<'b>> {
    let mut builder = ChartBuilder::on(root);
    builder
        .caption(title, ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(70);
    builder
}

fn draw<'a, DB, CT>(
    chart: &mut ChartContext<'a, DB, CT>,
    series: &[Series],
) -> Result<(), Box<dyn Error>>
where
    DB: DrawingBackend + 'a,
    DB::ErrorType: 'static,
    CT: CoordTranslate<From = (f64, f64)>,
{
    for (index, s) in series.iter().enumerate() {
        let color = PALETTE[index % PALETTE.len()].to_rgba();
        match s.mark {
            Mark::Line => chart
                .draw_series(LineSeries::new(
                    s.points.iter().copied(),
                    color.stroke_width(2),
                ))?
                .label(s.label.clone())
                .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], color)),
            Mark::Theory => chart
                .draw_series(LineSeries::new(
                    s.points.iter().copied(),
                    BLACK.stroke_width(1),
                ))?
                .label(s.label.clone())
                .legend(|(x, y)| PathElement::new([(x, y), (x + 20, y)], BLACK)),
            Mark::Points => chart
                .draw_series(
                    s.points
                        .iter()
                        .map(move |&p| Circle::new(p, 4, color.filled())),
                )?
                .label(s.label.clone())
                .legend(move |(x, y)| Circle::new((x + 10, y), 4, color.filled())),
        };
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .border_style(BLACK)
        .background_style(WHITE.mix(0.85))
        .draw()?;
    Ok(())
}

/// Distinguishable line colours (Okabe-Ito, without yellow).
const PALETTE: [RGBColor; 7] = [
    RGBColor(0, 114, 178),
    RGBColor(213, 94, 0),
    RGBColor(0, 158, 115),
    RGBColor(204, 121, 167),
    RGBColor(230, 159, 0),
    RGBColor(86, 180, 233),
    RGBColor(120, 120, 120),
];

type Range = (f64, f64);

fn ranges(series: &[Series], axes: Axes) -> (Range, Range) {
    let bounds = |pick: fn(&(f64, f64)) -> f64| {
        let values = series.iter().flat_map(|s| s.points.iter().map(pick));
        let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
        if !lo.is_finite() {
            return (0.0, 1.0);
        }
        match axes {
            Axes::Linear => {
                let pad = ((hi - lo) * 0.05).max(1e-12);
                (lo - pad, hi + pad)
            }
            Axes::LogLog => (lo / 1.5, hi * 1.5),
        }
    };
    (bounds(|p| p.0), bounds(|p| p.1))
}
