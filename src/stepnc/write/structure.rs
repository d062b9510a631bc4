//! Writing the programme structure: project, workplans, executables,
//! setups, workpieces.

use super::*;

impl<'p> W<'p> {
    pub fn project(&mut self) -> Value {
        let p = self.p;
        let root = self.reserve();
        let plan = self.workplan(&p.main_workplan);
        let workpieces = list(
            p.its_workpieces
                .iter()
                .map(|&w| self.workpiece(w))
                .collect(),
        );
        let params = vec![
            s(&p.id),
            plan,
            workpieces,
            self.opt_raw(&p.owner),
            self.opt_raw(&p.release),
            self.opt_raw(&p.status),
        ];
        self.fill(root, "PROJECT", params);
        Value::Ref(root)
    }

    fn workplan(&mut self, wp: &Workplan) -> Value {
        let elements = list(wp.elements.iter().map(|e| self.executable(e)).collect());
        let params = vec![
            s(&wp.id),
            elements,
            self.opt_raw(&wp.channel),
            opt(wp.setup.as_ref().map(|st| self.setup(st))),
            self.opt_raw(&wp.effect),
        ];
        self.add("WORKPLAN", params)
    }

    fn executable(&mut self, e: &Executable) -> Value {
        match e {
            Executable::Workingstep(ws) => {
                let params = vec![
                    s(&ws.id),
                    self.plane(&ws.secplane),
                    self.feature(ws.feature),
                    self.operation(ws.operation),
                    self.opt_raw(&ws.effect),
                ];
                self.add("MACHINING_WORKINGSTEP", params)
            }
            Executable::Rapid(rm) => {
                let params = vec![
                    s(&rm.id),
                    self.plane(&rm.secplane),
                    self.opt_toolpath_list(&rm.toolpath),
                    self.opt_raw(&rm.tool_direction),
                ];
                self.add("RAPID_MOVEMENT", params)
            }
            Executable::Workplan(wp) => self.workplan(wp),
            Executable::ProgramStop { id } => self.add("PROGRAM_STOP", vec![s(id)]),
            Executable::OptionalStop { id } => self.add("OPTIONAL_STOP", vec![s(id)]),
            Executable::DisplayMessage { id, text } => {
                self.add("DISPLAY_MESSAGE", vec![s(id), s(text)])
            }
            Executable::Other(raw) => self.raw(raw),
        }
    }

    fn setup(&mut self, st: &Setup) -> Value {
        let params = vec![
            s(&st.id),
            opt(st.origin.as_ref().map(|o| self.placement(o))),
            self.plane(&st.secplane),
            list(
                st.workpiece_setups
                    .iter()
                    .map(|ws| self.workpiece_setup(ws))
                    .collect(),
            ),
        ];
        self.add("SETUP", params)
    }

    fn workpiece_setup(&mut self, ws: &WorkpieceSetup) -> Value {
        let params = vec![
            self.workpiece(ws.workpiece),
            self.placement(&ws.origin),
            self.opt_raw(&ws.offset),
            self.opt_raw(&ws.restricted_area),
            self.raw_list(&ws.instructions),
        ];
        self.add("WORKPIECE_SETUP", params)
    }

    pub fn workpiece(&mut self, id: WorkpieceId) -> Value {
        if let Some(&n) = self.workpieces.get(&id) {
            return Value::Ref(n);
        }
        let n = self.reserve();
        self.workpieces.insert(id, n);
        let w = self.p.workpiece(id);
        let material = opt(w.material.as_ref().map(|m| {
            let props = self.raw_list(&m.properties);
            self.add(
                "MATERIAL",
                vec![s(&m.standard_identifier), s(&m.material_identifier), props],
            )
        }));
        let params = vec![
            s(&w.id),
            material,
            or(w.global_tolerance),
            opt(w.rawpiece.map(|r| self.workpiece(r))),
            self.opt_raw(&w.geometry),
            opt(w.bounding.as_ref().map(|b| self.bounding(b))),
            list(w.clamping_positions.iter().map(|c| self.point(c)).collect()),
        ];
        self.fill(n, "WORKPIECE", params);
        Value::Ref(n)
    }

    fn bounding(&mut self, b: &Bounding) -> Value {
        match b {
            Bounding::Block {
                name,
                position,
                size,
            } => {
                let params = vec![
                    s(name),
                    self.placement(position),
                    r(size[0]),
                    r(size[1]),
                    r(size[2]),
                ];
                self.add("BLOCK", params)
            }
            Bounding::Other(raw) => self.raw(raw),
        }
    }
}
