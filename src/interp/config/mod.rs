//! What a LinuxCNC configuration sets for a run (dialect capability
//! `var-and-ini-files`; `cncc canon --ini FILE --var-file FILE`): the
//! parameter file ([`var_file`]) and the `[RS274NGC]` settings of an INI
//! file ([`ini`]) that change what a program does. Remaps, HAL pins and
//! embedded Python are not read.

pub mod ini;
pub mod var_file;

use super::Interp;
use std::collections::BTreeMap;
use std::path::PathBuf;
use std::sync::{Arc, Mutex};

/// The settings of one run (all off by default: rs274 with no INI and an
/// empty parameter file).
#[derive(Clone, Debug, Default)]
pub struct Rs274Config {
    /// The parameter file's values, set before the run starts.
    pub parameters: Option<var_file::VarFile>,
    /// `[RS274NGC]SUBROUTINE_PATH`: folders searched for called programs
    /// after the program's own.
    pub subroutine_path: Vec<PathBuf>,
    /// The INI file, when `#<_ini[SECTION]NAME>` may read it
    /// (`[RS274NGC]INI_VARS`, on unless 0).
    pub ini_vars: Option<Arc<ini::Ini>>,
    /// `[RS274NGC]ORIENT_OFFSET`: added to every M19 angle, degrees.
    pub orient_offset: f64,
    /// `[RS274NGC]DISABLE_G92_PERSISTENCE`: the G92 offset (#5210-#5219)
    /// starts at 0 and is written as 0.
    pub disable_g92_persistence: bool,
    /// `[RS274NGC]DISABLE_FANUC_STYLE_SUB`: `M98` is an error.
    pub disable_fanuc_subs: bool,
    /// Where the run leaves its parameters at the end (for writing the
    /// parameter file back), when [`Self::parameters`] is given.
    pub final_parameters: FinalParameters,
}

/// The parameters a run ended with, filled in when it ends.
#[derive(Clone, Debug, Default)]
pub struct FinalParameters(pub Arc<Mutex<Option<BTreeMap<u32, f64>>>>);

impl FinalParameters {
    pub fn take(&self) -> Option<BTreeMap<u32, f64>> {
        self.0.lock().ok()?.take()
    }
}

/// The offset parameters #5221.. of work offset `k` (1..=9), axis `i`
/// (0..=8), and its rotation (`i` = 9).
fn work_parameter(k: usize, i: usize) -> u32 {
    5201 + 20 * k as u32 + i as u32
}

impl Rs274Config {
    /// Sets the parameter file's values before the first block: stored
    /// parameters as they are, the offsets into the machine state (rs274's
    /// `init`: #5220 picks the work offset, 1 when out of 1..=9; the G92
    /// offset applies when #5210 is not 0). Values are in machine units.
    pub fn apply(&self, it: &mut Interp<'_, '_>) {
        let Some(file) = &self.parameters else { return };
        let mut pars = file.values.clone();
        if self.disable_g92_persistence {
            for n in 5210..=5219 {
                pars.insert(n, 0.0);
            }
        }
        let get = |n: u32| pars.get(&n).copied().unwrap_or(0.0);
        let to_mm = match it.opts.machine_units {
            crate::ir::LengthUnit::Mm => 1.0,
            crate::ir::LengthUnit::Inch => super::state::MM_PER_INCH,
        };
        let len = |i: usize, v: f64| {
            if super::state::State::is_linear(i) {
                v * to_mm
            } else {
                v
            }
        };
        for (&n, &v) in &pars {
            if super::predefined::numbered(it, n).is_none() {
                it.params.set_numbered(n, Some(v));
            }
        }
        let index = (get(5220) + 0.0001) as i64;
        it.state.g5x_index = if (1..=9).contains(&index) {
            index as u32
        } else {
            1
        };
        for k in 1..=9 {
            for i in 0..9 {
                it.state.g5x[k][i] = len(i, get(work_parameter(k, i)));
            }
            it.state.g5x_rotation[k] = get(work_parameter(k, 9));
        }
        for i in 0..9 {
            it.state.g92[i] = len(i, get(5211 + i as u32));
        }
        it.state.g92_flag = get(5210);
        it.state.g92_applied = it.state.g92_flag != 0.0;
    }

    /// Keeps the parameters the run ends with, for writing back: every
    /// number the file had and the persistent ones, as the program would
    /// read them (vacant: 0).
    pub fn keep_final(&self, it: &Interp<'_, '_>) {
        let Some(file) = &self.parameters else { return };
        let numbers = file.values.keys().copied().chain(var_file::persistent());
        let mut out = BTreeMap::new();
        for n in numbers {
            let zeroed = self.disable_g92_persistence && (5210..=5219).contains(&n);
            let v = if zeroed {
                0.0
            } else {
                it.read_numbered(n).unwrap_or(0.0)
            };
            out.insert(n, v);
        }
        if let Ok(mut slot) = self.final_parameters.0.lock() {
            *slot = Some(out);
        }
    }
}
