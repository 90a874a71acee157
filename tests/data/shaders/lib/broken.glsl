// Included by syntax_error.comp. Line 5 below uses an undeclared name on purpose.

uint broken_value() {
  uint value = 1u;
  value = value + undeclared_name;
  return value;
}
