# A student's answers to the assignment (test_assignment.py), each the right side of
# `name = ...` in the ASCII maths kinetics reads.
q1 = "3 M/(2 m c^2)"
q2 = "-3 M/(16 c) - m c w^2/4"
q3 = "3 M/(8 c) - 3/8 m c w^2"
q4 = "2/3 m c^2 w"
