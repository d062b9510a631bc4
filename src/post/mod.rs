//! `cncc post`: a STEP-NC feature project (CC2) becomes a program for a
//! target dialect that calls the target's own canned cycles.
//!
//! Pipeline: [`plan`] resolves the workplan into workingsteps placed in
//! workpiece coordinates; each workingstep is written with the templates
//! the target's spec declares (`<post-template>`), read from `--post-dir`
//! or the built-in `posts/<dialect>/` of the spec or one it extends
//! ([`templates`], [`render`]), filled with values already
//! formatted by the target's number rules ([`values`]); features the target
//! has no cycle for become explicit toolpaths ([`paths`]). The finished
//! text is then read back with the target's own front end: a posted
//! program that does not read cleanly is an error, never output.
//!
//! Which cycle a feature becomes is data: the target's spec declares the
//! templates it has (`pocket_rect` on the 840D, none on Fanuc: explicit
//! moves); a template the post needs and the spec does not declare is a
//! refusal naming both (E0900). Tapping: [`tapping`]. Heidenhain: drilling cycles (CYCL DEF
//! 200/201/202, 203 or 205 for pecking: `pecking.rs`, 206/207 tapping)
//! called with `L X.. Y.. R0 FMAX M99` or `PATTERN DEF` + `CYCL CALL
//! PAT`, CYCL DEF 251/252 pockets, 232 faces, 253 slots
//! (`slot_cycle.rs`), CYCL DEF 32 tolerance, TOOL DEF and BLK FORM.

mod angles;
mod chipload;
mod explicit;
mod faces;
pub mod features;
pub mod fixture;
pub mod frame;
mod group;
mod hole_mill;
mod holes;
mod kept;
mod milling;
mod names;
pub mod paths;
mod pecking;
pub mod plan;
mod pocket_g12;
mod pocket_general;
mod pockets;
mod prismatic;
mod raw_curves;
pub mod render;
mod slot_circle;
mod slot_cycle;
mod slot_cycles;
mod slots;
mod step;
pub mod summary;
mod tapping;
mod templates;
pub mod toolpaths;
pub mod validate;
pub mod values;

use crate::diag::{Code, Diagnostic};
use crate::dialect::DialectSpec;
use crate::stepnc::model::Project;
use render::Post;
pub use templates::{PostDir, Source as TemplateSource};
use values::{Fmt, Vals};

/// The templates `target` posts with (from `dir` or the built-in
/// folders), for `cncc dialects --templates`.
pub fn templates_of(
    target: &DialectSpec,
    dir: Option<&PostDir>,
) -> Result<Vec<TemplateSource>, Vec<Diagnostic>> {
    templates::resolve(target, dir)
}

/// A reason a project cannot be posted (or a note about what is not
/// carried), before it becomes a [`Diagnostic`].
#[derive(Clone, Debug, PartialEq)]
pub struct PostError {
    pub code: Code,
    pub message: String,
    pub help: String,
}

impl PostError {
    pub fn unsupported(what: &str, kind: &str) -> Self {
        PostError {
            code: Code::PostUnsupported,
            message: format!("`{what}`: {kind} cannot be posted"),
            help: "see `cncc explain E0900` for what each target can post".into(),
        }
    }
    pub fn broken(what: &str, why: &str) -> Self {
        PostError {
            code: Code::PostBadProject,
            message: format!("`{what}`: {why}"),
            help: "fix the entity in the STEP-NC file".into(),
        }
    }
    pub fn geometry(what: &str, why: String) -> Self {
        PostError {
            code: Code::PostGeometry,
            message: format!("`{what}`: {why}"),
            help: "choose a smaller tool or another strategy".into(),
        }
    }
    /// E0908: the validator found the feature outside the stock (or
    /// with no depth).
    pub fn outside(what: &str, why: String, help: String) -> Self {
        PostError {
            code: Code::PostOutsideStock,
            message: format!("`{what}`: {why}"),
            help,
        }
    }
    pub fn template(why: String) -> Self {
        PostError {
            code: Code::PostTemplate,
            message: why,
            help: "a template from --post-dir: fix it (the values each template gets: docs/posts.md); a built-in one: a bug, please report it".into(),
        }
    }
    pub fn into_diagnostic(self) -> Diagnostic {
        Diagnostic::new(self.code, self.message).help(self.help)
    }
}

/// A posted program and the warnings about what it could not carry
/// (each also named in a comment in the program).
#[derive(Clone, Debug)]
pub struct Posted {
    pub text: String,
    pub warnings: Vec<Diagnostic>,
    /// What each workingstep was posted as.
    pub summary: Vec<summary::PostedStep>,
}

/// Posts `project` for `target` (the contract `cncc port --features`
/// uses): the program text, or every reason it cannot be written.
pub fn post_project(project: &Project, target: &DialectSpec) -> Result<String, Vec<Diagnostic>> {
    post(project, target).map(|p| p.text)
}

/// Posts `project` for `target` with its built-in templates, with the
/// warnings.
pub fn post(project: &Project, target: &DialectSpec) -> Result<Posted, Vec<Diagnostic>> {
    post_with(project, target, None)
}

/// Posts `project` for `target`, its templates overridden file by file
/// by those in `dir` (`--post-dir`).
pub fn post_with(
    project: &Project,
    target: &DialectSpec,
    dir: Option<&PostDir>,
) -> Result<Posted, Vec<Diagnostic>> {
    let post = Post::for_spec(target, dir)?;
    let can_tilt = target.has(crate::dialect::Capability::TiltedWorkingPlane);
    let items = plan::plan_for(project, can_tilt).map_err(into_diags)?;
    let found = validate::validate(project, &items, &plan::setup_frame(project));
    if !found.errors.is_empty() {
        let mut d = into_diags(found.errors);
        d.extend(found.warnings);
        return Err(d);
    }
    let mut w = Writer {
        post: &post,
        target,
        fmt: Fmt::new(&target.numbers),
        out: String::new(),
        warnings: found.warnings,
        current_tool: None,
        defined_tools: Vec::new(),
        coolant_on: false,
        step: String::new(),
        summary: Vec::new(),
    };
    step::write_program(&mut w, project, &items).map_err(into_diags)?;
    if let Some(v) = w.fmt.too_large.get() {
        return Err(vec![Diagnostic::new(
            Code::ValueOutOfRange,
            format!(
                "the value {v} is too large for {} ({} digits before the point at most)",
                target.name, target.numbers.integer_digits
            ),
        )
        .help(
            "check the units and the values of the STEP-NC file; nothing was posted",
        )]);
    }
    read_back(&w.out, target)?;
    Ok(Posted {
        text: w.out,
        warnings: w.warnings,
        summary: w.summary,
    })
}

fn into_diags(errs: Vec<PostError>) -> Vec<Diagnostic> {
    errs.into_iter().map(PostError::into_diagnostic).collect()
}

/// Reads the posted text with the target's front end; any error is ours.
fn read_back(text: &str, target: &DialectSpec) -> Result<(), Vec<Diagnostic>> {
    let (_, diags) = crate::driver::read_program(text, crate::span::FileId(u32::MAX), target);
    let errors: Vec<Diagnostic> = diags
        .into_iter()
        .filter(|d| d.is_error())
        .map(|d| {
            let line = d
                .span()
                .map(|s| line_of(text, s.start as usize))
                .unwrap_or_default();
            Diagnostic::new(
                Code::PostReadBack,
                format!(
                    "the posted program does not read back: {} {} at `{}`",
                    d.code.code(),
                    d.message,
                    line
                ),
            )
            .help("a bug in the post-processor; please report it")
        })
        .collect();
    if errors.is_empty() {
        Ok(())
    } else {
        Err(errors)
    }
}

fn line_of(text: &str, at: usize) -> &str {
    let at = at.min(text.len());
    let start = text[..at].rfind('\n').map(|i| i + 1).unwrap_or(0);
    let end = text[at..].find('\n').map(|i| at + i).unwrap_or(text.len());
    &text[start..end]
}

/// The output being written, with the target's templates and numbers.
pub(crate) struct Writer<'a> {
    pub post: &'a Post,
    /// The target: its `<text>` table escapes every text posted.
    pub target: &'a DialectSpec,
    pub fmt: Fmt,
    pub out: String,
    pub warnings: Vec<Diagnostic>,
    pub current_tool: Option<u32>,
    /// Tools whose data the program has defined.
    pub defined_tools: Vec<u32>,
    /// Coolant (flood or mist) was switched on and not off since.
    pub coolant_on: bool,
    /// The workingstep being written (its id), for a refusal.
    pub step: String,
    /// What each workingstep was posted as (`--summary`).
    pub summary: Vec<summary::PostedStep>,
}

impl Writer<'_> {
    /// Renders template `name` (which must exist) into the output.
    /// A template the target's spec does not declare is a refusal
    /// naming the target and the template (E0900).
    pub fn emit(&mut self, name: &str, vals: Vals) -> Result<(), PostError> {
        if !self.post.has(name) {
            return Err(self.undeclared(name));
        }
        let text = self.post.render(name, &vals).map_err(PostError::template)?;
        if let Some(s) = self.summary.last_mut().filter(|s| s.open) {
            s.rendered(name);
        }
        self.out.push_str(&text);
        if !self.out.ends_with('\n') {
            self.out.push('\n');
        }
        Ok(())
    }

    /// E0900: the target's spec declares no template `name`.
    fn undeclared(&self, name: &str) -> PostError {
        let name = name.trim_end_matches(".j2");
        let what = crate::dialect::POST_TEMPLATES
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, d)| *d)
            .unwrap_or("this");
        let at = if self.step.is_empty() {
            String::new()
        } else {
            format!("`{}`: ", self.step)
        };
        PostError {
            code: Code::PostUnsupported,
            message: format!(
                "{at}{} ({}) cannot post {what}: its spec declares no `{name}` post template",
                self.target.name, self.target.id
            ),
            help: format!(
                "declare `<post-template name=\"{name}\"/>` in the spec and give `{name}.j2` with --post-dir (docs/posts.md), or post to another target"
            ),
        }
    }

    /// A comment line in the target's syntax.
    pub fn comment(&mut self, text: &str) -> Result<(), PostError> {
        let text = self.safe_text(text, "comment.j2");
        self.emit("comment.j2", Vals::new().set("text", text))
    }

    /// STEP-NC text (a project id, a workingstep's name, a message) made
    /// safe for the comment that template `template` writes it in: the
    /// target's `<text>` table decides, and a change is a warning.
    pub fn safe_text(&mut self, text: &str, template: &str) -> String {
        use crate::dialect::text::TextForm;
        let paren = self.post.source(template).contains('(');
        let text = values::comment_text_in(text, !paren);
        let form = if paren {
            TextForm::Paren
        } else {
            TextForm::Semicolon
        };
        let e = self.target.text.escape(&text, form, false);
        if let Some(d) = crate::emit::writer::text_warning(&self.target.name, &e, None) {
            self.warnings.push(d);
        }
        e.text
    }

    /// The spindle speed word's value (rpm, unsigned): whole rpm where the
    /// target's S takes no decimals (`integer-spindle-speed`), with a
    /// warning when that rounds.
    pub fn spindle(&mut self, rpm: f64) -> Result<String, PostError> {
        let rpm = rpm.abs();
        if !self
            .target
            .has(crate::dialect::Capability::IntegerSpindleSpeed)
        {
            return Ok(self.fmt.feed(rpm));
        }
        let whole = rpm.round();
        if (whole - rpm).abs() > 1e-9 {
            let what = format!(
                "spindle speed {} rpm exactly: written S{} (the target's S takes whole rpm)",
                self.fmt.plain(rpm, 3),
                self.fmt.plain(whole, 0)
            );
            if !self.warnings.iter().any(|d| d.message.ends_with(&what)) {
                self.not_carried(&what)?;
            }
        }
        Ok(self.fmt.plain(whole, 0))
    }

    /// A value the target cannot carry: a comment in the program and a
    /// warning.
    pub fn not_carried(&mut self, what: &str) -> Result<(), PostError> {
        self.comment(&format!("NOT POSTED: {what}"))?;
        self.warnings.push(
            Diagnostic::new(Code::PostNotCarried, format!("not posted: {what}"))
                .help("named in a comment in the posted program"),
        );
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ex1_posts_to_every_target_with_a_post() {
        for id in ["siemens840d", "fanuc", "haas", "linuxcnc", "heidenhain"] {
            let spec = crate::dialect::builtin(id).unwrap();
            let p = post(&fixture::ex1(), &spec).unwrap_or_else(|e| panic!("{id}: {e:?}"));
            assert!(p.text.contains("WS FINISH POCKET1"), "{id}");
        }
    }

    #[test]
    fn a_dialect_without_templates_has_no_post() {
        let spec = crate::dialect::builtin("iso6983").unwrap();
        let e = post(&fixture::ex1(), &spec).unwrap_err();
        assert_eq!(e[0].code, Code::PostNoTarget);
    }

    #[test]
    fn a_template_the_spec_does_not_declare_is_a_refusal_naming_it() {
        let mut spec = (*crate::dialect::builtin("fanuc").unwrap()).clone();
        spec.post_templates.retain(|t| t.name != "drill");
        let e = post(&fixture::ex1(), &spec).unwrap_err();
        assert_eq!(e[0].code, Code::PostUnsupported, "{e:?}");
        assert_eq!(
            e[0].message,
            "`WS DRILL HOLE1`: Fanuc 0i/18i/30i (Custom Macro B) (fanuc) cannot post the drilling cycle: its spec declares no `drill` post template"
        );
    }
}
