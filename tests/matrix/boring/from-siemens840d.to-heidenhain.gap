port: CYCLE85 with its own feeds FFR/RFF is refused by to_word (E0610: G85 feeds at F) before to_tnc, though CYCL DEF 201 has Q206/Q208 for them; CYCLE85/CYCLE89 without FFR/RFF map to 201
