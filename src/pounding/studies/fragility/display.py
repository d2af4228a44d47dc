"""A fragility study as Jupyter shows it (``_repr_html_`` of
:class:`~pounding.studies.fragility.analysis.FragilityAnalysis` and
:class:`~pounding.studies.fragility.runner.FragilityOutcome`): every limit state's
lognormal fragility (median θ in the study's intensity measure [g], dispersion β, with their
bootstrap intervals; from the stripes and from the IDA capacities), the gap for the target
probability of pounding [mm], the runs, and the fragility curves
(:func:`pounding.plot.fragility.plot_fragility`) as an inline PNG. Nothing is written;
matplotlib is imported only when it is shown."""

from __future__ import annotations

from typing import Any

from pounding.result.display import html_table, png_uri

__all__ = ["fragility_html"]


def fragility_html(analysis: Any, outcome_rows: list[tuple[str, Any]] | None = None) -> str:
    """The HTML summary of a :class:`~pounding.studies.fragility.analysis.FragilityAnalysis`
    (``outcome_rows``: more rows for the head table, e.g. the wall time of the study)."""
    from pounding.plot.fragility import plot_fragility

    cases = analysis.cases
    im = cases.im_label
    ga = analysis.gap
    head: list[tuple[str, Any]] = [
        ("study", str(cases.config.name)), ("intensity measure", im),
        ("records", len(analysis.records)), ("levels", len(analysis.levels)),
        ("runs", analysis.n_runs), ("failed runs", analysis.n_failed),
        (f"gap for P(pounding) = {ga.target:g} at {ga.needed.at:g} g, lognormal fit [mm]",
         ga.gap_fit * 1e3),
        (f"its {100 * cases.config.bootstrap.confidence:g} % interval [mm]",
         f"{ga.gap_fit_ci[0] * 1e3:.4g} – {ga.gap_fit_ci[1] * 1e3:.4g}"),
        ("the same from the records [mm]", ga.gap_empirical * 1e3),
        *(outcome_rows or [])]
    states = []
    for r in analysis.limit_states:
        gap = "base model" if r.gap is None else f"{r.gap * 1e3:g} mm"
        for method, e in (("stripes (MLE)", r.msa), ("IDA capacities", r.ida)):
            states.append((r.spec.label, gap, method, e.median,
                           f"{e.median_ci[0]:.4g} – {e.median_ci[1]:.4g}", e.beta,
                           f"{e.beta_ci[0]:.3g} – {e.beta_ci[1]:.3g}"))
    figure = plot_fragility(analysis)
    return ('<div class="pounding-fragility"><strong>pounding fragility study</strong>'
            + html_table(head, ("quantity", "value"))
            + html_table(states, ("limit state", "gap", "fit", "median θ [g]",
                                  "θ interval [g]", "β [-]", "β interval [-]"),
                         caption=f"fragility curves P(exceeded | {im})")
            + f'<img alt="fragility curves" src="{png_uri(figure)}"></div>')
