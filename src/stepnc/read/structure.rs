//! Reading the programme structure: project, workplans and their
//! executables, setups, workpieces.

use super::*;

impl<'f> Rd<'f> {
    pub fn project(&mut self, i: &'f Instance) -> R<Project> {
        let id = string(arg(i, 0)?)?;
        self.ids.push((id.clone(), "project", i.span));
        let wp = self.inst(arg(i, 1)?)?;
        let main_workplan = self.workplan(wp)?;
        let mut its_workpieces = Vec::new();
        for w in self.insts(arg(i, 2)?)? {
            its_workpieces.push(self.workpiece(w)?);
        }
        let owner = self.opt_raw(arg(i, 3)?)?;
        let release = self.opt_raw(arg(i, 4)?)?;
        let status = self.opt_raw(arg(i, 5)?)?;
        let mut p = std::mem::take(&mut self.p);
        p.id = id;
        p.main_workplan = main_workplan;
        p.its_workpieces = its_workpieces;
        p.owner = owner;
        p.release = release;
        p.status = status;
        Ok(p)
    }

    pub fn workplan(&mut self, i: &'f Instance) -> R<Workplan> {
        expect(i, &["WORKPLAN"], "a WORKPLAN")?;
        if !self.open.insert(i.id) {
            return Err(too_deep(i.span, "a workplan contains itself"));
        }
        self.enter(i.span)?;
        let r = self.workplan_body(i);
        self.leave();
        self.open.remove(&i.id);
        let w = r?;
        self.ids.push((w.id.clone(), "executable", i.span));
        Ok(w)
    }

    fn workplan_body(&mut self, i: &'f Instance) -> R<Workplan> {
        let id = string(arg(i, 0)?)?;
        let mut elements = Vec::new();
        for e in self.insts(arg(i, 1)?)? {
            match self.executable(e) {
                Ok(x) => elements.push(x),
                Err(f) => self.hard(f),
            }
        }
        let channel = self.opt_raw(arg(i, 2)?)?;
        let setup = match self.opt_inst(arg(i, 3)?)? {
            Some(s) => Some(self.setup(s)?),
            None => None,
        };
        let effect = self.opt_raw(arg(i, 4)?)?;
        Ok(Workplan {
            id,
            elements,
            channel,
            setup,
            effect,
        })
    }

    fn executable(&mut self, i: &'f Instance) -> R<Executable> {
        Ok(match ent(i) {
            "WORKPLAN" => Executable::Workplan(self.workplan(i)?),
            "MACHINING_WORKINGSTEP" => self.or_raw(
                i,
                |rd, i| rd.workingstep(i).map(Executable::Workingstep),
                Executable::Other,
            )?,
            "RAPID_MOVEMENT" => self.or_raw(
                i,
                |rd, i| rd.rapid(i).map(Executable::Rapid),
                Executable::Other,
            )?,
            "PROGRAM_STOP" => Executable::ProgramStop {
                id: self.exec_id(i)?,
            },
            "OPTIONAL_STOP" => Executable::OptionalStop {
                id: self.exec_id(i)?,
            },
            "DISPLAY_MESSAGE" => Executable::DisplayMessage {
                id: self.exec_id(i)?,
                text: string(arg(i, 1)?)?,
            },
            "PARALLEL" | "SELECTIVE" | "NON_SEQUENTIAL" | "SET_MARK" | "WAIT_FOR_MARK"
            | "LOAD_TOOL" | "UNLOAD_TOOL" | "RETURN_HOME" | "INDEX_TABLE" | "EXCHANGE_PALLET"
            | "INDEX_PALLET" => Executable::Other(self.raw(i)?),
            _ => {
                return Err(fail(
                    i.entity_span,
                    format!(
                    "expected an executable (workingstep, workplan, NC function), found {} (#{})",
                    i.entity, i.id
                ),
                ))
            }
        })
    }

    fn exec_id(&mut self, i: &'f Instance) -> R<String> {
        let id = string(arg(i, 0)?)?;
        self.ids.push((id.clone(), "executable", i.span));
        Ok(id)
    }

    fn workingstep(&mut self, i: &'f Instance) -> R<MachiningWorkingstep> {
        let id = string(arg(i, 0)?)?;
        let sp = self.inst(arg(i, 1)?)?;
        let secplane = self.plane(sp)?;
        let f = self.inst(arg(i, 2)?)?;
        let feature = self.feature(f)?;
        let o = self.inst(arg(i, 3)?)?;
        let operation = self.operation(o)?;
        let effect = self.opt_raw(arg(i, 4)?)?;
        self.ids.push((id.clone(), "executable", i.span));
        Ok(MachiningWorkingstep {
            id,
            secplane,
            feature,
            operation,
            effect,
        })
    }

    fn rapid(&mut self, i: &'f Instance) -> R<RapidMovement> {
        let id = string(arg(i, 0)?)?;
        let sp = self.inst(arg(i, 1)?)?;
        let secplane = self.plane(sp)?;
        let toolpath = self.opt_toolpath_list(arg(i, 2)?)?;
        let tool_direction = self.opt_raw(arg(i, 3)?)?;
        self.ids.push((id.clone(), "executable", i.span));
        Ok(RapidMovement {
            id,
            secplane,
            toolpath,
            tool_direction,
        })
    }

    fn setup(&mut self, i: &'f Instance) -> R<Setup> {
        expect(i, &["SETUP"], "a SETUP")?;
        let id = string(arg(i, 0)?)?;
        let origin = match self.opt_inst(arg(i, 1)?)? {
            Some(o) => Some(self.placement(o)?),
            None => None,
        };
        let sp = self.inst(arg(i, 2)?)?;
        let secplane = self.plane(sp)?;
        let mut workpiece_setups = Vec::new();
        for w in self.insts(arg(i, 3)?)? {
            workpiece_setups.push(self.workpiece_setup(w)?);
        }
        Ok(Setup {
            id,
            origin,
            secplane,
            workpiece_setups,
        })
    }

    fn workpiece_setup(&mut self, i: &'f Instance) -> R<WorkpieceSetup> {
        expect(i, &["WORKPIECE_SETUP"], "a WORKPIECE_SETUP")?;
        let w = self.inst(arg(i, 0)?)?;
        let workpiece = self.workpiece(w)?;
        let o = self.inst(arg(i, 1)?)?;
        let origin = self.placement(o)?;
        let offset = self.opt_raw(arg(i, 2)?)?;
        let restricted_area = self.opt_raw(arg(i, 3)?)?;
        let instructions = self.raw_list(arg(i, 4)?)?;
        Ok(WorkpieceSetup {
            workpiece,
            origin,
            offset,
            restricted_area,
            instructions,
        })
    }

    /// A workpiece, read once and shared.
    pub fn workpiece(&mut self, i: &'f Instance) -> R<WorkpieceId> {
        if let Some(&id) = self.workpieces.get(&i.id) {
            return Ok(id);
        }
        expect(i, &["WORKPIECE"], "a WORKPIECE")?;
        if !self.open.insert(i.id) {
            return Err(fail(i.span, "a workpiece is its own rawpiece"));
        }
        let w = self.workpiece_body(i);
        self.open.remove(&i.id);
        let w = w?;
        let id = WorkpieceId(self.p.workpieces.len() as u32);
        self.p.workpieces.push(w);
        self.workpieces.insert(i.id, id);
        Ok(id)
    }

    fn workpiece_body(&mut self, i: &'f Instance) -> R<Workpiece> {
        let id = string(arg(i, 0)?)?;
        let material = match self.opt_inst(arg(i, 1)?)? {
            Some(m) => Some(self.material(m)?),
            None => None,
        };
        let global_tolerance = opt_real(arg(i, 2)?)?;
        let rawpiece = match self.opt_inst(arg(i, 3)?)? {
            Some(r) => Some(self.workpiece(r)?),
            None => None,
        };
        let geometry = self.opt_raw(arg(i, 4)?)?;
        let bounding = match self.opt_inst(arg(i, 5)?)? {
            Some(b) => Some(self.or_raw(b, |rd, b| rd.block(b), Bounding::Other)?),
            None => None,
        };
        let mut clamping_positions = Vec::new();
        for c in self.insts(arg(i, 6)?)? {
            clamping_positions.push(self.point(c)?);
        }
        Ok(Workpiece {
            id,
            material,
            global_tolerance,
            rawpiece,
            geometry,
            bounding,
            clamping_positions,
        })
    }

    fn material(&mut self, i: &'f Instance) -> R<Material> {
        expect(i, &["MATERIAL"], "a MATERIAL")?;
        Ok(Material {
            standard_identifier: string(arg(i, 0)?)?,
            material_identifier: string(arg(i, 1)?)?,
            properties: self.raw_list(arg(i, 2)?)?,
        })
    }

    /// A BLOCK; other bounding geometry is kept as written.
    fn block(&mut self, i: &'f Instance) -> R<Bounding> {
        if ent(i) != "BLOCK" {
            return Err(fail(
                i.entity_span,
                "only BLOCK bounding geometry is modelled",
            ));
        }
        let pos = self.inst(arg(i, 1)?)?;
        Ok(Bounding::Block {
            name: string(arg(i, 0)?)?,
            position: self.placement(pos)?,
            size: [real(arg(i, 2)?)?, real(arg(i, 3)?)?, real(arg(i, 4)?)?],
        })
    }
}
