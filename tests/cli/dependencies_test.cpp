// Each required library is linked and does real work: a broken install fails here first.
#include <catch2/catch.hpp>

#include <hdf5.h>
#include <sqlite3.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

TEST_CASE("SQLite stores and returns a row") {
  sqlite3* db = nullptr;
  REQUIRE(sqlite3_open(":memory:", &db) == SQLITE_OK);
  REQUIRE(sqlite3_exec(db, "CREATE TABLE t(x REAL); INSERT INTO t VALUES (2.5);", nullptr, nullptr, nullptr) ==
          SQLITE_OK);
  sqlite3_stmt* stmt = nullptr;
  REQUIRE(sqlite3_prepare_v2(db, "SELECT x FROM t", -1, &stmt, nullptr) == SQLITE_OK);
  REQUIRE(sqlite3_step(stmt) == SQLITE_ROW);
  CHECK(sqlite3_column_double(stmt, 0) == 2.5);
  sqlite3_finalize(stmt);
  sqlite3_close(db);
}

TEST_CASE("HDF5 writes and reads back a dataset") {
  const auto path = std::filesystem::temp_directory_path() / "aerobreak_dependency_test.h5";
  const std::vector<double> written{1.0, 2.0, 3.0};
  hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  REQUIRE(file >= 0);
  hsize_t dims[1] = {written.size()};
  hid_t space = H5Screate_simple(1, dims, nullptr);
  hid_t set = H5Dcreate2(file, "x", H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  REQUIRE(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, written.data()) >= 0);
  H5Dclose(set);
  H5Sclose(space);
  H5Fclose(file);

  std::vector<double> read(3, 0.0);
  file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  set = H5Dopen2(file, "x", H5P_DEFAULT);
  REQUIRE(H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, read.data()) >= 0);
  H5Dclose(set);
  H5Fclose(file);
  std::filesystem::remove(path);
  CHECK(read == written);
}

TEST_CASE("nlohmann-json round-trips a document") {
  const auto doc = nlohmann::json::parse(R"({"gamma_over_kn": 0.001, "N": [256, 1024]})");
  CHECK(doc.at("N").at(1).get<int>() == 1024);
  CHECK(nlohmann::json::parse(doc.dump()) == doc);
}
