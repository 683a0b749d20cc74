// The entry point of the render_layer_check_* programs (render/CMakeLists.txt): each links one
// stage's objects with only the stages below it, so that a call pointing up fails to link.
int main() { return 0; }
