//! Reading explicit toolpaths: toolpath lists, cutter location
//! trajectories, feed stops, speed profiles.

use super::*;

impl<'f> Rd<'f> {
    pub fn opt_toolpath_list(&mut self, p: &'f Param) -> R<Option<Vec<Toolpath>>> {
        match p.value {
            Value::Null => Ok(None),
            _ => self.toolpath_list_at(p).map(Some),
        }
    }

    pub fn toolpath_list_at(&mut self, p: &'f Param) -> R<Vec<Toolpath>> {
        let l = self.inst(p)?;
        expect(l, &["TOOLPATH_LIST"], "a TOOLPATH_LIST")?;
        let mut out = Vec::new();
        for t in self.insts(arg(l, 0)?)? {
            out.push(self.or_raw(t, |rd, t| rd.toolpath(t), Toolpath::Other)?);
        }
        Ok(out)
    }

    fn toolpath(&mut self, i: &'f Instance) -> R<Toolpath> {
        let e = ent(i);
        if e != "CUTTER_LOCATION_TRAJECTORY" && e != "FEEDSTOP" {
            return Err(fail(i.entity_span, "not a toolpath cncc models"));
        }
        let base = ToolpathBase {
            priority: boolean(arg(i, 0)?)?,
            kind: toolpath_type(enumeration(arg(i, 1)?)?),
            speed: self.speed(arg(i, 2)?)?,
            technology: self.opt_technology(arg(i, 3)?)?,
            machine_functions: self.opt_machine_functions(arg(i, 4)?)?,
        };
        Ok(if e == "FEEDSTOP" {
            Toolpath::Feedstop {
                base,
                dwell: real(arg(i, 5)?)?,
            }
        } else {
            let c = self.inst(arg(i, 6)?)?;
            Toolpath::CutterLocation {
                base,
                direction: opt_bool(arg(i, 5)?)?,
                basic_curve: self.curve(c)?,
                tool_axis: self.opt_curve(arg(i, 7)?)?,
                surface_normal: self.opt_curve(arg(i, 8)?)?,
            }
        })
    }

    fn speed(&mut self, p: &'f Param) -> R<Option<ToolpathSpeed>> {
        Ok(Some(match &p.value {
            Value::Null => return Ok(None),
            Value::Typed(t, inner) if t == "POSITIVE_RATIO_MEASURE" => {
                ToolpathSpeed::Ratio(real(inner)?)
            }
            Value::Typed(t, inner) if t == "SPEED_NAME" => {
                ToolpathSpeed::Named(enumeration(inner)?.to_string())
            }
            Value::Ref(_) => {
                let i = self.inst(p)?;
                ToolpathSpeed::Other(self.raw(i)?)
            }
            _ => {
                return Err(fail(
                    p.span,
                    "its_speed is TOOLPATH_SPEED, POSITIVE_RATIO_MEASURE(..) or SPEED_NAME(..)",
                ))
            }
        }))
    }
}

fn toolpath_type(e: &str) -> ToolpathType {
    match e {
        "APPROACH" => ToolpathType::Approach,
        "LIFT" => ToolpathType::Lift,
        "CONNECT" => ToolpathType::Connect,
        "NON_CONTACT" => ToolpathType::NonContact,
        "CONTACT" => ToolpathType::Contact,
        "TRAJECTORY_PATH" => ToolpathType::TrajectoryPath,
        other => ToolpathType::Other(other.to_string()),
    }
}
