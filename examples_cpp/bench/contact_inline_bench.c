/* Per-contact cost of the full Hertz-Mindlin contact called one contact at a time from a C loop
 * (as the LAMMPS/LIGGGHTS plugins do): the library's dc_contact_force against the header-only
 * dc_contact_force_inline (same bits), in the same run. Thread CPU time, the two variants
 * interleaved, fastest of 9 rounds of 20 x 10,000 contacts (each call advances its history).
 * Model as the settled bed of docs/benchmarks.md (E = 5 MPa, nu = 0.3, e = 0.5, Mindlin, mu = 0.5,
 * e_t = 0.5); overlaps up to 1e-5 m of 1 mm spheres, random normals, spins up to 0.5 rad/s.
 * Run: build-bench/bench/contact_inline_bench (cmake target contact_inline_bench). */
#define _POSIX_C_SOURCE 199309L
#include <demcontact_inline.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
static double now(void){struct timespec t;clock_gettime(CLOCK_THREAD_CPUTIME_ID,&t);return t.tv_sec+1e-9*t.tv_nsec;}
static unsigned long long s=88172645463325252ull; static double u(void){s^=s<<13;s^=s>>7;s^=s<<17;return (s>>11)/9007199254740992.0;}
int main(void) {
  dc_contact_spec sp; dc_contact_spec_init(&sp); sp.normal=DC_NORMAL_HERTZ; sp.damping=DC_DAMPING_RESTITUTION; sp.e_n=0.5; sp.E1=sp.E2=5e6; sp.nu1=sp.nu2=0.3; sp.tangential=DC_TANGENTIAL_MINDLIN; sp.mu=0.5; sp.e_t=0.5;
  dc_contact_model m; if(dc_contact_model_init(&sp,&m)) return 1;
  enum{N=10000}; static dc_contact_state st[N]; static double h1[N][10], h2[N][10]; dc_contact_result r;
  for(int i=0;i<N;i++){double *n=st[i].n; n[0]=u()-.5;n[1]=u()-.5;n[2]=u()-.5; double l=sqrt(n[0]*n[0]+n[1]*n[1]+n[2]*n[2]); for(int j=0;j<3;j++){n[j]/=l; st[i].v1[j]=0.01*(u()-.5); st[i].v2[j]=0; st[i].w1[j]=(u()-.5); st[i].w2[j]=(u()-.5);} st[i].overlap=1e-5*u(); st[i].r1=st[i].r2=1e-3; st[i].m1=st[i].m2=1.05e-5;}
  double best[2]={1e9,1e9}; double sink=0;
  for(int t=0;t<9;t++) for(int v=0;v<2;v++){ double t0=now(); for(int k=0;k<20;k++) for(int i=0;i<N;i++){ int q = v==0 ? dc_contact_force(&m,&st[i],6e-6,h1[i],10,&r) : dc_contact_force_inline(&m,&st[i],6e-6,h2[i],10,&r); sink+=r.force[0]+q;} double ns=(now()-t0)*1e9/(20.0*N); if(ns<best[v]) best[v]=ns; }
  printf("dc_contact_force %.1f ns/contact, dc_contact_force_inline %.1f ns/contact (ratio %.2f) [%g]\n", best[0], best[1], best[1]/best[0], sink*0);
  return 0; }
