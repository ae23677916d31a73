// five lines
int A();
int B();
int C();
int D();
