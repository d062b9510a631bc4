port: R/DEF variables, FOR/labels to Q parameters and FN jumps not mapped yet (E0613)
