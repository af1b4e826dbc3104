// Placeholder entry point while the driver is written.
int main() { return 0; }
