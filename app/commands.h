/* The porelab commands; each takes the arguments after its name and returns the exit
 * code (options.h). */
#ifndef PL_APP_COMMANDS_H
#define PL_APP_COMMANDS_H

int pl_cmd_run(int argc, char **argv);
int pl_cmd_still(int argc, char **argv);
int pl_cmd_info(int argc, char **argv);
int pl_cmd_flags(int argc, char **argv);
int pl_cmd_compare(int argc, char **argv); /* app/cmd_compare.c */
int pl_cmd_sweep(int argc, char **argv);         /* cmd_sweep.c */
int pl_cmd_collect(int argc, char **argv);       /* cmd_collect.c */
int pl_cmd_export_lammps(int argc, char **argv); /* cmd_export_lammps.c */
int pl_cmd_import_lammps(int argc, char **argv); /* cmd_import_lammps.c */
int pl_cmd_view(int argc, char **argv); /* app/window/cmd_view.c (gl) */

#endif
