#version 450
// A drop-in whose path names no built-in shader (a typo): refused before the run.
void main() {}
