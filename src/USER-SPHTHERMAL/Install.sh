# Install/uninstall USER-SPHTHERMAL in LAMMPS's src/ (traditional make build)
# mode = 0/1/2 for uninstall/install/update. Needs the SPH package.

mode=$1

if (test $mode = 1) then
  if (test ! -e ../atom_vec_sph.h) then
    echo "Must install SPH package with USER-SPHTHERMAL (make yes-sph)"
    exit 1
  fi
fi

action () {
  if (test $mode = 0) then
    rm -f ../$1
  elif (! cmp -s $1 ../$1) then
    cp $1 ..
    if (test $mode = 2) then
      echo "  updating src/$1"
    fi
  fi
}

for file in *.cpp *.h; do
  action $file
done
