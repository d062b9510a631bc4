toolpath: a rigid tap (CYCLE84) is given the modal feed F, not pitch x speed, so --verify sees F100 against the port's correct G84 F500 (src/toolpath/track.rs RigidTap)
