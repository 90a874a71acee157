// Second include level of counting.comp.
uint nested_answer() { return 42u; }
