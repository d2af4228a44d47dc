"""`pounding run` and `pounding demo`."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer
from rich.text import Text

from pounding.cli import options as opt
from pounding.cli.app import app, console
from pounding.cli.running import progress_bar, sigterm_as_interrupt
from pounding.cli.tables import Col, literal, print_table


def _run(model_file: Path, out: Path | None, overwrite: bool, figures: bool | None,
         label: str, code_check: Path | None = None) -> None:
    from pounding.cli.messages import EXIT_INTERRUPTED, error_line
    from pounding.config import load_config
    from pounding.io.output_folder import default_out_dir
    from pounding.run_file import run_config

    check = None
    if code_check is not None:  # (the report package only where asked for)
        from pounding.report.code_check import other_model, read_code_check

        check = read_code_check(code_check)
    cfg = load_config(model_file)
    if check is not None:  # a check of this model, or refused before the run
        why = other_model(check, cfg.build()[0])
        if why is not None:
            raise ValueError(f"--code-check: {code_check} is a check of another model "
                             f"({why}); check {model_file.name} with pounding code-check")
    target = out if out is not None else default_out_dir(model_file)
    try:
        with sigterm_as_interrupt(), progress_bar(label) as progress:
            result = run_config(cfg, target, overwrite=overwrite, figures=figures,
                                progress=progress)
    except KeyboardInterrupt:
        error_line(f"stopped: the run was interrupted, so nothing was written to {target} "
                   "(an earlier output there is as it was); run the same command again")
        raise typer.Exit(EXIT_INTERRUPTED) from None
    if check is not None:  # kept for the report's Code check section
        from pounding.report.code_check import attach_code_check

        console.print(Text(f"code check kept: {attach_code_check(result.out_dir, check)}"))
    from pounding.cli.run_tables import print_run_summary

    print_run_summary(result)


@app.command("run")
def run_cmd(
    model: Annotated[Path, typer.Argument(help="TOML model file (see docs/running.md).",
                                          show_default=False)],
    out: opt.Out = None,
    overwrite: opt.Overwrite = False,
    figures: opt.Figures = None,
    code_check: opt.CodeCheckDir = None,
) -> None:
    """Simulate a model file and write time histories, impacts, summary and figures.

    Examples:

      pounding run examples/seed_sdof_pair.toml --out results/sdof

      pounding run model.toml --no-figures --overwrite
    """
    _run(model, out, overwrite, figures, f"simulating {model.name}", code_check)


@app.command("demo")
def demo_cmd(
    out: opt.DemoOut = Path("pounding-demo"),
    overwrite: opt.OverwriteDemo = True,
    figures: opt.Figures = None,
) -> None:
    """Two 10-storey buildings pounding under El Centro 1940: the bundled example
    two_10_storey.toml (see it with `pounding examples`).

    Examples:

      pounding demo

      pounding demo --out results/demo --no-figures
    """
    from pounding.example_files import DEMO, example_path

    _run(example_path(DEMO), out, overwrite, figures, "demo: two 10-storey buildings")


@app.command("examples")
def examples_cmd(
    copy: Annotated[Path | None, typer.Option(
        "--copy", metavar="DIR", help="Copy every example (and its README) into the folder "
                                      "DIR, made if missing.", show_default=False)] = None,
    overwrite: opt.OverwriteCopy = False,
) -> None:
    """List the example model, sweep, spectrum and fragility files of pounding, or copy them.

    Examples:

      pounding examples

      pounding examples --copy my-examples && pounding run my-examples/seed_sdof_pair.toml
    """
    from pounding.example_files import copy_examples, example_path, examples

    if copy is not None:
        files = copy_examples(copy, overwrite=overwrite)
        console.print(Text.assemble(f"copied {len(files)} files into ", (str(copy), "bold"),
                                    ": " + ", ".join(p.name for p in files)))
        return
    print_table(console, f"Examples (in {example_path('seed_sdof_pair').parent})",
                [Col("file", "left"), Col("kind", "left"), Col("what it shows", "left", wrap=True)],
                [(literal(e.name), e.kind, literal(e.description)) for e in examples()])
    console.print("Run one with `pounding run FILE` (a sweep: `pounding sweep FILE`, a fragility "
                  "study: `pounding fragility FILE`, a pushover: `pounding pushover FILE`); copy them with `pounding examples --copy "
                  "DIR`.", highlight=False)
