// six lines
int A();
int B();
int C();
int D();
int E();
